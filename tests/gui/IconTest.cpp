// The tool icons embedded under ":/icons": each exists, is a 24x24 SVG and draws something in
// one colour. Offscreen platform, no display needed. Leaves icons.png (all icons, 4x) in the
// build folder for a look.

#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#include <QTest>

#include <cstdlib>

namespace {

const char* const icon_names[] = {"open",        "save",        "run",          "pause",         "stop",
                                  "mesh",        "select",      "draw-region",  "draw-joint",    "fixed-point",
                                  "roller",      "point-load",  "edge-pressure", "measurement-point",
                                  "fit-view",    "undo",        "redo",         "contacts",     "query-line",   "bolt",
                                  "water-table"};

QString resource(const char* name) { return QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)); }

QImage render(QSvgRenderer& renderer, int size)
{
    QImage image(size, size, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    renderer.render(&painter);
    painter.end();
    return image;
}

}  // namespace

class IconTest : public QObject {
    Q_OBJECT

private slots:
    void everyIconRenders_data() {
        QTest::addColumn<QString>("path");
        for (const char* name : icon_names) QTest::newRow(name) << resource(name);
    }

    void everyIconRenders() {
        QFETCH(QString, path);
        QVERIFY2(QFile::exists(path), qPrintable(path));
        QSvgRenderer renderer(path);
        QVERIFY(renderer.isValid());
        QCOMPARE(renderer.viewBoxF(), QRectF(0, 0, 24, 24));

        const QImage image = render(renderer, 48);
        QVERIFY(!image.isNull());
        int inked = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (c.alpha() < 128) continue;
                ++inked;
                // One colour: #2e3440 (anti-aliased edges are only lighter in alpha).
                QVERIFY2(std::abs(c.red() - 0x2e) < 24 && std::abs(c.green() - 0x34) < 24 &&
                             std::abs(c.blue() - 0x40) < 24,
                         qPrintable(QStringLiteral("%1: pixel %2,%3 is %4").arg(path).arg(x).arg(y).arg(c.name())));
            }
        const int total = image.width() * image.height();
        QVERIFY2(inked > total / 50, qPrintable(QStringLiteral("%1: only %2 pixels drawn").arg(path).arg(inked)));
        QVERIFY2(inked < total * 3 / 4, qPrintable(QStringLiteral("%1: %2 pixels drawn").arg(path).arg(inked)));
    }

    void contactSheet() {
        constexpr int size = 96, gap = 8;
        const int count = int(std::size(icon_names));
        QImage sheet(count * (size + gap) + gap, size + 2 * gap, QImage::Format_ARGB32);
        sheet.fill(Qt::white);
        QPainter painter(&sheet);
        for (int i = 0; i < count; ++i) {
            QSvgRenderer renderer(resource(icon_names[i]));
            renderer.render(&painter, QRectF(gap + i * (size + gap), gap, size, size));
        }
        painter.end();
        // Every cell holds a drawing: ink (pixels far from the white ground) covering a fair
        // share of it, and none spills into the gaps between cells.
        for (int i = 0; i < count; ++i) {
            int ink = 0;
            for (int y = gap; y < gap + size; ++y)
                for (int x = gap + i * (size + gap); x < gap + i * (size + gap) + size; ++x)
                    ink += qGray(sheet.pixel(x, y)) < 200;
            QVERIFY2(ink > size * size / 50, qPrintable(QStringLiteral("icon %1 is (nearly) blank: %2 ink pixels")
                                                             .arg(QString::fromLatin1(icon_names[i]))
                                                             .arg(ink)));
            for (int y = 0; y < sheet.height(); ++y)
                QCOMPARE(qGray(sheet.pixel(gap + i * (size + gap) + size + gap / 2, y)), 255);
        }
        QVERIFY(sheet.save(QStringLiteral(MCDDA_TEST_OUTPUT_DIR "/icons.png")));
    }
};

QTEST_MAIN(IconTest)
#include "IconTest.moc"
