#include "widgets/ModelTree.hpp"

#include "session/DisplayUnits.hpp"

#include <QCoreApplication>
#include <QHeaderView>
#include <QLocale>
#include <QStringList>
#include <QTreeWidgetItemIterator>

#include <cmath>
#include <cstddef>

namespace mcdda::gui {

namespace {

constexpr int kind_role = Qt::UserRole;
constexpr int index_role = Qt::UserRole + 1;
constexpr int ring_role = Qt::UserRole + 2;

QString to_qt(const std::string& s) { return QString::fromStdString(s); }

/// A point in the user's locale; "; " between the numbers where the decimal mark is a comma.
QString point_text(const Point2& p)
{
    const QLocale locale;
    const QString separator = locale.decimalPoint() == QStringLiteral(",") ? QStringLiteral("; ") : QStringLiteral(", ");
    return QLatin1Char('(') + locale.toString(p.x, 'g', 6) + separator + locale.toString(p.y, 'g', 6) + QLatin1Char(')');
}

constexpr int pressure_role = Qt::UserRole + 3;  ///< an edge pressure's value (Pa), for a change of units

/// A pressure in the stress unit chosen (Results ▸ Units): kPa or MPa, and automatically MPa from
/// 1 MPa on (not "1e+07 Pa").
QString pressure_text(double pa)
{
    const view::StressUnit unit = DisplayUnits::instance()->stress();
    const bool mpa = unit == view::StressUnit::MPa || (unit == view::StressUnit::Automatic && std::abs(pa) >= 1e6);
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);  // as the forms write numbers
    return mpa ? QCoreApplication::translate("mcdda::gui::ModelTree", "pressure %1 MPa").arg(locale.toString(pa / 1e6, 'g', 6))
               : QCoreApplication::translate("mcdda::gui::ModelTree", "pressure %1 kPa").arg(locale.toString(pa / 1e3, 'g', 6));
}

QString name_or(const std::string& name, const QString& fallback) { return name.empty() ? fallback : to_qt(name); }

QTreeWidgetItem* row(QTreeWidgetItem* parent, const QString& name, const QString& details, const ItemRef& ref = {})
{
    auto* item = new QTreeWidgetItem(parent, {name, details});
    if (ref.valid()) {
        item->setData(0, kind_role, static_cast<int>(ref.kind));
        item->setData(0, index_role, ref.index);
        item->setData(0, ring_role, ref.ring);
    }
    return item;
}

ItemRef ref_of(const QTreeWidgetItem* item)
{
    if (!item || !item->data(0, kind_role).isValid()) return {};
    return {static_cast<ItemRef::Kind>(item->data(0, kind_role).toInt()), item->data(0, index_role).toInt(),
            item->data(0, ring_role).toInt(), -1};
}

}  // namespace

ModelTree::ModelTree(QWidget* parent) : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("modelTree"));
    setColumnCount(2);
    setHeaderLabels({tr("Item"), tr("Details")});
    header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    setSelectionMode(QAbstractItemView::SingleSelection);
    connect(this, &QTreeWidget::itemSelectionChanged, this, [this] {
        if (!quiet_) emit itemChosen(selectedItem());
    });
    // Only the user's choice counts (refresh() expands and collapses rows itself).
    connect(this, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        if (!quiet_ && item == blocks_) blocks_expanded_ = true;
    });
    connect(this, &QTreeWidget::itemCollapsed, this, [this](QTreeWidgetItem* item) {
        if (!quiet_ && item == blocks_) blocks_expanded_ = false;
    });
    connect(DisplayUnits::instance(), &DisplayUnits::changed, this, [this] {
        for (QTreeWidgetItemIterator it(this); *it; ++it)
            if (const QVariant pa = (*it)->data(1, pressure_role); pa.isValid()) (*it)->setText(1, pressure_text(pa.toDouble()));
    });
}

void ModelTree::refresh(const Model& m, const Preprocessed* p)
{
    using Kind = ItemRef::Kind;
    const ItemRef selected = selectedItem();
    quiet_ = true;
    clear();
    blocks_ = nullptr;
    auto group = [&](const QString& title, std::size_t count) {
        auto* item = new QTreeWidgetItem(this, {title, QString::number(count)});
        item->setExpanded(true);
        return item;
    };
    QTreeWidgetItem* regions = group(tr("Regions"), m.regions.size());
    for (std::size_t i = 0; i < m.regions.size(); ++i) {
        const Region& r = m.regions[i];
        const QString material = r.material >= 0 && static_cast<std::size_t>(r.material) < m.materials.size()
                                     ? to_qt(m.materials[static_cast<std::size_t>(r.material)].name)
                                     : tr("no material");
        QTreeWidgetItem* region = row(regions, name_or(r.name, tr("region %1").arg(i + 1)),
                                      tr("%1, %n vertices", "", static_cast<int>(r.boundary.size())).arg(material),
                                      {Kind::Region, static_cast<int>(i)});
        for (std::size_t h = 0; h < r.holes.size(); ++h)
            row(region, tr("hole %1").arg(h + 1), tr("%n vertices", "", static_cast<int>(r.holes[h].size())),
                {Kind::Region, static_cast<int>(i), static_cast<int>(h + 1)});
        region->setExpanded(true);
    }

    // Blocks come from pre-processing, which may lag behind the model by one edit.
    const std::size_t block_count = p ? p->blocks.size() : 0;
    blocks_ = group(tr("Blocks"), block_count);
    for (std::size_t b = 0; b < block_count; ++b) {
        const Block& block = p->blocks[b];
        const QString material = block.material >= 0 && static_cast<std::size_t>(block.material) < p->model.materials.size()
                                     ? to_qt(p->model.materials[static_cast<std::size_t>(block.material)].name)
                                     : tr("no material");
        const auto& begin = p->mesh.block_triangle_begin;
        const int elements = b + 1 < begin.size() ? begin[b + 1] - begin[b] : 0;
        row(blocks_, tr("block %1").arg(b + 1),
            tr("%1, %2 m², %n elements", "", elements).arg(material, QLocale().toString(block.area, 'g', 4)));
    }
    blocks_->setExpanded(blocks_expanded_);

    QTreeWidgetItem* joints = group(tr("Joints"), m.joints.size());
    QTreeWidgetItem* explicit_joints = new QTreeWidgetItem(joints, {tr("Explicit")});
    std::vector<QTreeWidgetItem*> sets;
    for (std::size_t i = 0; i < m.joint_sets.size(); ++i) {
        const JointSet& set = m.joint_sets[i];
        QString details = tr("spacing %1 m").arg(QLocale().toString(set.spacing, 'g', 6));
        if (set.persistence < 1.0)
            details += tr(", persistence %1 %, joints %2 m long").arg(QLocale().toString(100.0 * set.persistence, 'g', 6), QLocale().toString(set.trace_length, 'g', 6));
        sets.push_back(new QTreeWidgetItem(joints, {tr("Set %1").arg(name_or(set.name, QString::number(i + 1))), details}));
    }
    int explicit_count = 0;
    for (std::size_t i = 0; i < m.joints.size(); ++i) {
        const Joint& j = m.joints[i];
        const bool generated = j.joint_set >= 0 && static_cast<std::size_t>(j.joint_set) < sets.size();
        QTreeWidgetItem* parent = generated ? sets[static_cast<std::size_t>(j.joint_set)] : explicit_joints;
        if (!generated) ++explicit_count;
        const QString details = j.points.empty() ? QString()
                                                 : tr("%1 to %2").arg(point_text(j.points.front()), point_text(j.points.back()));
        row(parent, name_or(j.name, tr("joint %1").arg(i + 1)), details,
            generated ? ItemRef{} : ItemRef{Kind::Joint, static_cast<int>(i)});
    }
    explicit_joints->setText(1, QString::number(explicit_count));
    explicit_joints->setExpanded(true);
    QTreeWidgetItem* materials = group(tr("Materials"), m.materials.size() + m.joint_materials.size());
    for (const Material& x : m.materials) row(materials, to_qt(x.name), tr("rock/soil"));
    for (const JointMaterial& x : m.joint_materials) row(materials, to_qt(x.name), tr("joint"));
    QTreeWidgetItem* supports = group(tr("Supports"), m.fixed_points.size() + m.rollers.size());
    for (std::size_t i = 0; i < m.fixed_points.size(); ++i)
        row(supports, to_qt(m.fixed_points[i].name), tr("fixed point %1").arg(point_text(m.fixed_points[i].point)),
            {Kind::FixedPoint, static_cast<int>(i)});
    for (std::size_t i = 0; i < m.rollers.size(); ++i)
        row(supports, to_qt(m.rollers[i].name),
            tr("roller %1 to %2").arg(point_text(m.rollers[i].from), point_text(m.rollers[i].to)),
            {Kind::Roller, static_cast<int>(i)});
    // The earthquake: its records, the base they shake, the dashpot boundaries (these two selectable).
    const bool compliant = m.base_motion.kind == BaseMotion::Kind::Compliant;
    if (!m.ground_motions.empty() || !m.absorbing_boundaries.empty() || m.base_motion.present()) {
        QTreeWidgetItem* quake = group(tr("Earthquake"), m.ground_motions.size() + m.absorbing_boundaries.size() + (compliant ? 1 : 0));
        for (const GroundMotion& g : m.ground_motions)
            row(quake, to_qt(g.name), g.file.empty() ? tr("record of %n point(s)", "", static_cast<int>(g.points.size()))
                                                     : tr("record %1").arg(to_qt(g.file)));
        if (m.base_motion.kind == BaseMotion::Kind::Rigid) row(quake, tr("rigid base"), tr("every support moves"));
        if (compliant)
            row(quake, tr("compliant base"), tr("dashpots %1 to %2").arg(point_text(m.base_motion.from), point_text(m.base_motion.to)),
                {Kind::CompliantBase, 0});
        for (std::size_t i = 0; i < m.absorbing_boundaries.size(); ++i)
            row(quake, to_qt(m.absorbing_boundaries[i].name),
                tr("dashpots %1 to %2").arg(point_text(m.absorbing_boundaries[i].from), point_text(m.absorbing_boundaries[i].to)),
                {Kind::AbsorbingBoundary, static_cast<int>(i)});
    }
    QTreeWidgetItem* loads = group(tr("Loads"), m.point_loads.size() + m.edge_pressures.size());
    for (std::size_t i = 0; i < m.point_loads.size(); ++i)
        row(loads, to_qt(m.point_loads[i].name), tr("point load at %1").arg(point_text(m.point_loads[i].point)),
            {Kind::PointLoad, static_cast<int>(i)});
    for (std::size_t i = 0; i < m.edge_pressures.size(); ++i)
        row(loads, to_qt(m.edge_pressures[i].name), pressure_text(m.edge_pressures[i].pressure),
            {Kind::EdgePressure, static_cast<int>(i)})
            ->setData(1, pressure_role, m.edge_pressures[i].pressure);
    QTreeWidgetItem* points = group(tr("Measurement points"), m.measurement_points.size());
    for (std::size_t i = 0; i < m.measurement_points.size(); ++i)
        row(points, to_qt(m.measurement_points[i].name), point_text(m.measurement_points[i].point),
            {Kind::MeasurementPoint, static_cast<int>(i)});
    if (!m.bolts.empty()) {
        QTreeWidgetItem* bolts = group(tr("Bolts"), m.bolts.size());
        for (const Bolt& b : m.bolts)
            row(bolts, to_qt(b.name), tr("%1 to %2, EA %3 MN/m").arg(point_text(b.from), point_text(b.to)).arg(b.stiffness / 1e6));
    }
    // Stages, read-only: what each does (editing them here is still to come).
    if (!m.stages.empty()) {
        QTreeWidgetItem* stages = group(tr("Stages"), m.stages.size());
        auto region_names = [&](const std::vector<int>& indices) {
            QStringList names;
            for (int r : indices)
                if (r >= 0 && static_cast<std::size_t>(r) < m.regions.size()) names << to_qt(m.regions[r].name);
            return names.join(QStringLiteral(", "));
        };
        auto item_names = [](const std::vector<std::string>& names) {
            QStringList list;
            for (const std::string& n : names) list << to_qt(n);
            return list.join(QStringLiteral(", "));
        };
        for (std::size_t i = 0; i < m.stages.size(); ++i) {
            const Stage& st = m.stages[i];
            QStringList what{tr("%n step(s)", "", st.analysis.steps)};
            if (!st.excavate.empty()) what << tr("excavates %1").arg(region_names(st.excavate));
            if (!st.activate.empty()) what << tr("builds %1").arg(region_names(st.activate));
            if (!st.install.empty()) what << tr("installs %1").arg(item_names(st.install));
            if (!st.remove.empty()) what << tr("removes %1").arg(item_names(st.remove));
            if (!st.materials.empty()) what << tr("%n material change(s)", "", static_cast<int>(st.materials.size()));
            if (st.water)
                what << (st.water->present() ? tr("water table of %1 points").arg(st.water->piezometric_line.size())
                                             : tr("dry"));
            row(stages, tr("%1. %2").arg(i + 1).arg(to_qt(st.name)), what.join(QStringLiteral("; ")));
        }
    }
    // The model's water table, selectable like the lines drawn (the stages' are in their rows).
    if (m.water.present()) {
        QTreeWidgetItem* water = group(tr("Ground water"), 1);
        row(water, tr("water table"),
            tr("%1 points, γw %2 kN/m³").arg(m.water.piezometric_line.size()).arg(m.water.unit_weight / 1e3),
            {Kind::WaterTable, 0});
    }
    quiet_ = false;
    if (item_exists(m, selected)) selectItem(selected);
}

void ModelTree::selectItem(const ItemRef& ref)
{
    const ItemRef wanted = ref.valid() ? ref.whole() : ItemRef{};
    quiet_ = true;
    clearSelection();
    if (wanted.valid()) {
        for (QTreeWidgetItemIterator it(this); *it; ++it) {
            if (ref_of(*it) == wanted) {
                (*it)->setSelected(true);
                scrollToItem(*it);
                break;
            }
        }
    }
    quiet_ = false;
}

ItemRef ModelTree::selectedItem() const
{
    const QList<QTreeWidgetItem*> items = selectedItems();
    return items.isEmpty() ? ItemRef{} : ref_of(items.front());
}

int ModelTree::blockCount() const { return blocks_ ? blocks_->childCount() : 0; }

}  // namespace mcdda::gui
