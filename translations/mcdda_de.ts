<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="23"/>
        <source>Pre- and post-processor for elastic-plastic discontinuous deformation analysis.</source>
        <translation>Pre- und Postprozessor für die elastisch-plastische diskontinuierliche Deformationsanalyse.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="28"/>
        <source>Model file (*.json) to open.</source>
        <translation>Zu öffnende Modelldatei (*.json).</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::MainWindow</name>
    <message>
        <location filename="../gui/MainWindow.cpp" line="49"/>
        <source>mcdda</source>
        <translation>mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="59"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="60"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="62"/>
        <source>Open a model file (*.json)</source>
        <translation>Eine Modelldatei öffnen (*.json)</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="63"/>
        <source>&amp;Reload</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="65"/>
        <source>Read the model file again, e.g. after editing it</source>
        <translation>Die Modelldatei erneut lesen, z. B. nachdem sie bearbeitet wurde</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="68"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="71"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="72"/>
        <source>&amp;Fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="74"/>
        <source>Show the whole model</source>
        <translation>Das ganze Modell zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="84"/>
        <source>&amp;Mesh</source>
        <translation>&amp;Netz</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="84"/>
        <source>Show the element edges</source>
        <translation>Die Elementkanten zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="85"/>
        <source>&amp;Joints</source>
        <translation>&amp;Klüfte</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="85"/>
        <source>Show the joint traces</source>
        <translation>Die Kluftspuren zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="86"/>
        <source>&amp;Supports</source>
        <translation>A&amp;uflager</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="86"/>
        <source>Show fixed points and rollers</source>
        <translation>Festpunkte und Rollenlager zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="87"/>
        <source>&amp;Loads</source>
        <translation>&amp;Lasten</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="87"/>
        <source>Show point loads and edge pressures</source>
        <translation>Punktlasten und Randdrücke zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="88"/>
        <source>Measurement &amp;points</source>
        <translation>&amp;Messpunkte</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="88"/>
        <source>Show the measurement points</source>
        <translation>Die Messpunkte zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="89"/>
        <source>Le&amp;gend</source>
        <translation>Le&amp;gende</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="89"/>
        <source>Show the legend</source>
        <translation>Die Legende zeigen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="93"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="94"/>
        <source>&amp;About mcdda</source>
        <translation>Ü&amp;ber mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="95"/>
        <source>About mcdda</source>
        <translation>Über mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="96"/>
        <source>&lt;b&gt;mcdda %1&lt;/b&gt;&lt;p&gt;Pre- and post-processor for elastic-plastic discontinuous deformation analysis.&lt;/p&gt;&lt;p&gt;Drag with the left or middle mouse button to pan, turn the wheel to zoom, press F to fit.&lt;/p&gt;</source>
        <translation>&lt;b&gt;mcdda %1&lt;/b&gt;&lt;p&gt;Pre- und Postprozessor für die elastisch-plastische diskontinuierliche Deformationsanalyse.&lt;/p&gt;&lt;p&gt;Zum Verschieben mit der linken oder mittleren Maustaste ziehen, zum Zoomen das Mausrad drehen, zum Einpassen F drücken.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="109"/>
        <source>Messages about the model appear here.</source>
        <translation>Meldungen zum Modell erscheinen hier.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="110"/>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="136"/>
        <source>x = %1 m   y = %2 m</source>
        <translation>x = %1 m   y = %2 m</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="155"/>
        <source>Open model</source>
        <translation>Modell öffnen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="156"/>
        <source>Model files (*.json);;All files (*)</source>
        <translation>Modelldateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="172"/>
        <source>Reading %1...</source>
        <translation>%1 wird gelesen...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="198"/>
        <source>%1 - mcdda</source>
        <translation>%1 - mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="202"/>
        <source>Model: %1</source>
        <translation>Modell: %1</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="206"/>
        <source>Times: read %1 ms, checked %2 ms, cut %3 ms, meshed %4 ms</source>
        <translation>Zeiten: gelesen %1 ms, geprüft %2 ms, zerlegt %3 ms, vernetzt %4 ms</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="212"/>
        <source>%1 blocks, %2 nodes, %3 elements, smallest angle %4°</source>
        <translation>%1 Blöcke, %2 Knoten, %3 Elemente, kleinster Winkel %4°</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/MainWindow.cpp" line="221"/>
        <source>Not meshed: %n error(s)</source>
        <translation>
            <numerusform>Nicht vernetzt: %n Fehler</numerusform>
            <numerusform>Nicht vernetzt: %n Fehler</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="233"/>
        <source>pre-processing stopped without a message</source>
        <translation>die Vorverarbeitung brach ohne Meldung ab</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/MainWindow.cpp" line="237"/>
        <source>... and %n more</source>
        <translation>
            <numerusform>... und %n weitere</numerusform>
            <numerusform>... und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="240"/>
        <source>Model not usable</source>
        <translation>Modell nicht verwendbar</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="241"/>
        <source>%1 could not be pre-processed.</source>
        <translation>%1 konnte nicht vorverarbeitet werden.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddJointCommand</name>
    <message>
        <location filename="../gui/document/Commands.cpp" line="39"/>
        <source>Add joint &quot;%1&quot;</source>
        <translation>Kluft „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddRegionCommand</name>
    <message>
        <location filename="../gui/document/Commands.cpp" line="18"/>
        <source>Add region &quot;%1&quot;</source>
        <translation>Bereich „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ModelDocument</name>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="38"/>
        <source>The model has no file yet; choose one with Save As.</source>
        <translation>Das Modell hat noch keine Datei; wählen Sie eine mit „Speichern unter“.</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="48"/>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetAnalysisSettingsCommand</name>
    <message>
        <location filename="../gui/document/Commands.cpp" line="78"/>
        <source>Change analysis settings</source>
        <translation>Berechnungseinstellungen ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetMaterialCommand</name>
    <message>
        <location filename="../gui/document/Commands.cpp" line="62"/>
        <source>Change material &quot;%1&quot;</source>
        <translation>Material „%1“ ändern</translation>
    </message>
</context>
</TS>
