<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>HistoryCsv</name>
    <message>
        <location filename="../gui/results/HistoryCsv.cpp" line="17"/>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryCsv.cpp" line="46"/>
        <source>%1 is empty</source>
        <translation>%1 ist leer</translation>
    </message>
</context>
<context>
    <name>ModelFields</name>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="23"/>
        <source>Young&apos;s modulus E</source>
        <translation>Elastizitätsmodul E</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="24"/>
        <source>Young&apos;s modulus E of the intact rock, &gt; 0</source>
        <translation>Elastizitätsmodul E des intakten Gesteins, &gt; 0</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="26"/>
        <source>Poisson&apos;s ratio ν</source>
        <translation>Querdehnzahl ν</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="27"/>
        <source>Poisson&apos;s ratio ν, in (−1, 0.5)</source>
        <translation>Querdehnzahl ν, in (−1; 0,5)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="29"/>
        <source>Unit weight γ</source>
        <translation>Wichte γ</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="30"/>
        <source>Unit weight γ = ρ g (the density is γ / 9.81 m/s²); loads the model through gravity</source>
        <translation>Wichte γ = ρ g (die Dichte ist γ / 9,81 m/s²); belastet das Modell über die Schwerkraft</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="260"/>
        <source>Mohr–Coulomb</source>
        <translation>Mohr–Coulomb</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="261"/>
        <source>Perfectly plastic with cohesion c and friction angle φ, non-associated flow by ψ, optional tension cut-off</source>
        <translation>Ideal plastisch mit Kohäsion c und Reibungswinkel φ, nicht-assoziiertes Fließen mit ψ, wahlweise Zugabschneidung</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="263"/>
        <source>Cohesion c</source>
        <translation>Kohäsion c</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="264"/>
        <source>Mohr–Coulomb cohesion c, ≥ 0</source>
        <translation>Mohr-Coulomb-Kohäsion c, ≥ 0</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="265"/>
        <source>Friction angle φ</source>
        <translation>Reibungswinkel φ</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="267"/>
        <source>Mohr–Coulomb friction angle φ, in [0°, 90°)</source>
        <translation>Mohr-Coulomb-Reibungswinkel φ, in [0°, 90°)</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="263"/>
        <source>Hoek–Brown</source>
        <translation>Hoek–Brown</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="264"/>
        <source>Generalised Hoek–Brown rock mass (2002): strength from σci, GSI, mi and the disturbance D</source>
        <translation>Verallgemeinertes Hoek–Brown-Gebirge (2002): Festigkeit aus σci, GSI, mi und dem Störungsgrad D</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="266"/>
        <source>Intact strength σci</source>
        <translation>Gesteinsfestigkeit σci</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="268"/>
        <source>Uniaxial compressive strength σci of the intact rock, &gt; 0</source>
        <translation>Einaxiale Druckfestigkeit σci des intakten Gesteins, &gt; 0</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="269"/>
        <source>GSI</source>
        <translation>GSI</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="271"/>
        <source>Geological Strength Index of the rock mass, 0 to 100 (100: intact rock)</source>
        <translation>Geological Strength Index des Gebirges, 0 bis 100 (100: intaktes Gestein)</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="272"/>
        <source>Intact constant mi</source>
        <translation>Gesteinskonstante mi</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="274"/>
        <source>Hoek–Brown constant mi of the intact rock, &gt; 0 (about 4 for claystone to 33 for granite)</source>
        <translation>Hoek–Brown-Konstante mi des intakten Gesteins, &gt; 0 (etwa 4 für Tonstein bis 33 für Granit)</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="275"/>
        <source>Disturbance D</source>
        <translation>Störungsgrad D</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="277"/>
        <source>Disturbance factor D by blasting and stress relaxation, 0 (undisturbed) to 1</source>
        <translation>Störungsgrad D durch Sprengen und Entspannung, 0 (ungestört) bis 1</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="278"/>
        <location filename="../solver/material/MohrCoulomb.cpp" line="268"/>
        <source>Dilation angle ψ</source>
        <translation>Dilatanzwinkel ψ</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="280"/>
        <source>Dilation angle ψ of the plastic flow (constant), in [0°, 90°)</source>
        <translation>Dilatanzwinkel ψ des plastischen Fließens (konstant), in [0°, 90°)</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="281"/>
        <source>Tension cut-off</source>
        <translation>Zugabschneidung</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="282"/>
        <source>the Hoek–Brown tensile strength</source>
        <translation>die Hoek–Brown-Zugfestigkeit</translation>
    </message>
    <message>
        <location filename="../solver/material/HoekBrown.cpp" line="283"/>
        <source>A tension cut-off below the Hoek–Brown tensile strength s σci/mb, ≥ 0; 0 = none but the criterion&apos;s own</source>
        <translation>Eine Zugabschneidung unter der Hoek–Brown-Zugfestigkeit s σci/mb, ≥ 0; 0 = nur die des Kriteriums</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="270"/>
        <source>Dilation angle ψ of the plastic flow, 0 ≤ ψ ≤ φ (ψ = φ: associated flow)</source>
        <translation>Dilatanzwinkel ψ des plastischen Fließens, 0 ≤ ψ ≤ φ (ψ = φ: assoziiertes Fließen)</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="271"/>
        <source>Tensile strength</source>
        <translation>Zugfestigkeit</translation>
    </message>
    <message>
        <location filename="../solver/material/MohrCoulomb.cpp" line="273"/>
        <source>Tension cut-off of the Mohr–Coulomb surface, ≥ 0; 0 = no tension</source>
        <translation>Zugfestigkeitsgrenze der Mohr-Coulomb-Fläche, ≥ 0; 0 = kein Zug</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="32"/>
        <source>Saturated unit weight γsat</source>
        <translation>Gesättigte Wichte γsat</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="33"/>
        <source>the unit weight</source>
        <translation>die Wichte</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="34"/>
        <source>Unit weight below the piezometric line; 0 = the unit weight γ there too</source>
        <translation>Wichte unterhalb der Piezometerlinie; 0 = auch dort die Wichte γ</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="43"/>
        <source>Friction angle φj</source>
        <translation>Reibungswinkel φj</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="44"/>
        <source>Coulomb friction angle of the joint surfaces, in [0°, 90°)</source>
        <translation>Coulomb-Reibungswinkel der Kluftflächen, in [0°, 90°)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="46"/>
        <source>Cohesion cj</source>
        <translation>Kohäsion cj</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="47"/>
        <source>Cohesion of the joint, ≥ 0; lost once the joint has slipped or opened</source>
        <translation>Kohäsion der Kluft, ≥ 0; geht verloren, sobald die Kluft gleitet oder sich öffnet</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="49"/>
        <source>Tensile strength tj</source>
        <translation>Zugfestigkeit tj</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="50"/>
        <source>Tensile strength of the joint, ≥ 0; 0 = the joint opens under any tension</source>
        <translation>Zugfestigkeit der Kluft, ≥ 0; 0 = die Kluft öffnet sich bei jedem Zug</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="52"/>
        <source>Normal stiffness kn</source>
        <translation>Normalsteifigkeit kn</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="53"/>
        <location filename="../solver/model/ModelFields.cpp" line="56"/>
        <location filename="../solver/model/ModelFields.cpp" line="92"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="53"/>
        <source>Normal stiffness per metre of thickness; 0 = the analysis penalty</source>
        <translation>Normalsteifigkeit je Meter Dicke; 0 = Penalty der Berechnung</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="55"/>
        <source>Shear stiffness ks</source>
        <translation>Schubsteifigkeit ks</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="56"/>
        <source>Shear stiffness; 0 = automatic</source>
        <translation>Schubsteifigkeit; 0 = automatisch</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="65"/>
        <source>Axial stiffness EA</source>
        <translation>Dehnsteifigkeit EA</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="67"/>
        <source>Axial stiffness EA of the bolt per metre of model thickness (bolt EA over the spacing out of plane), &gt; 0</source>
        <translation>Dehnsteifigkeit EA des Ankers je Meter Modelldicke (EA des Ankers durch seinen Abstand senkrecht zur Ebene), &gt; 0</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="69"/>
        <source>Strength</source>
        <translation>Tragkraft</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="70"/>
        <source>unbreakable</source>
        <translation>unzerstörbar</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="70"/>
        <source>Axial force at which the bolt breaks, per metre of model thickness; 0 = unbreakable</source>
        <translation>Axialkraft, bei der der Anker reißt, je Meter Modelldicke; 0 = unzerstörbar</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="72"/>
        <source>Pretension</source>
        <translation>Vorspannung</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="73"/>
        <source>Axial force when installed, per metre of model thickness, pulling the ends together; ≥ 0</source>
        <translation>Axialkraft beim Einbau, je Meter Modelldicke, zieht die Enden zusammen; ≥ 0</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="83"/>
        <source>Time step Δt</source>
        <translation>Zeitschritt Δt</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="85"/>
        <source>Initial and largest time step; it is cut automatically when a step moves too far or does not converge. In a static analysis time only orders the load steps</source>
        <translation>Anfänglicher und größter Zeitschritt; er wird automatisch verkleinert, wenn sich ein Schritt zu weit bewegt oder nicht konvergiert. In einer statischen Berechnung ordnet die Zeit nur die Laststufen</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="87"/>
        <source>Max displacement ratio</source>
        <translation>Max. Verschiebungsverhältnis</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="89"/>
        <source>Largest displacement in one step divided by the model size (Shi&apos;s g2)</source>
        <translation>Größte Verschiebung in einem Schritt geteilt durch die Modellgröße (g2 nach Shi)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="91"/>
        <source>Penalty</source>
        <translation>Kontaktsteifigkeit (Penalty)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="93"/>
        <source>Contact spring stiffness; 0 = automatic (from E)</source>
        <translation>Steifigkeit der Kontaktfedern; 0 = automatisch (aus E)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="95"/>
        <source>Dynamic ratio</source>
        <translation>Dynamikfaktor</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="97"/>
        <source>Fraction of the velocity carried into the next step of a dynamic analysis (1: none lost)</source>
        <translation>Anteil der Geschwindigkeit, der in einer dynamischen Berechnung in den nächsten Schritt übernommen wird (1: nichts geht verloren)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="99"/>
        <source>Equilibrium tolerance</source>
        <translation>Gleichgewichtstoleranz</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="101"/>
        <source>Out-of-balance force, relative to the force scale, below which a step&apos;s equilibrium iterations stop</source>
        <translation>Ungleichgewichtskraft, bezogen auf die Kraftskala, unter der die Gleichgewichtsiterationen eines Schritts enden</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="103"/>
        <source>Smallest load increment</source>
        <translation>Kleinstes Lastinkrement</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="105"/>
        <source>A static step that does not converge is halved down to this fraction of a step; failing there is a collapse</source>
        <translation>Ein statischer Schritt, der nicht konvergiert, wird bis auf diesen Bruchteil eines Schritts halbiert; scheitert er auch dort, ist es ein Versagen</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="107"/>
        <source>Equilibrium ratio</source>
        <translation>Gleichgewichtsgrenze</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="109"/>
        <source>A run whose unbalanced-force ratio ends above this is reported as not in equilibrium</source>
        <translation>Eine Berechnung, deren Ungleichgewichtsverhältnis am Ende darüber liegt, wird als nicht im Gleichgewicht gemeldet</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="111"/>
        <source>Factor of safety tolerance</source>
        <translation>Toleranz des Sicherheitsfaktors</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="113"/>
        <source>Strength reduction: the search for the factor of safety stops once the factors that stand and that do not differ by less than this fraction</source>
        <translation>Festigkeitsreduktion: die Suche nach dem Sicherheitsfaktor endet, sobald sich die Faktoren, bei denen das Modell steht und bei denen nicht, um weniger als diesen Bruchteil unterscheiden</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="115"/>
        <source>Newmark γ</source>
        <translation>Newmark-γ</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="117"/>
        <source>Dynamic analysis: Newmark&apos;s γ (β = (γ + ½)²/4). 0.7 damps the highest frequencies; 0.5 adds no numerical damping</source>
        <translation>Dynamische Berechnung: Newmarks γ (β = (γ + ½)²/4). 0,7 dämpft die höchsten Frequenzen; 0,5 fügt keine numerische Dämpfung hinzu</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="119"/>
        <source>Damping ratio</source>
        <translation>Dämpfungsgrad</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="121"/>
        <source>Dynamic analysis: Rayleigh damping as a fraction of critical damping (0: none)</source>
        <translation>Dynamische Berechnung: Rayleigh-Dämpfung als Anteil der kritischen Dämpfung (0: keine)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="123"/>
        <source>Damping frequency</source>
        <translation>Dämpfungsfrequenz</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="125"/>
        <source>Frequency at which the Rayleigh damping has the damping ratio (its least when no second frequency is given)</source>
        <translation>Frequenz, bei der die Rayleigh-Dämpfung den Dämpfungsgrad hat (ihr Minimum, wenn keine zweite Frequenz angegeben ist)</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="127"/>
        <source>Second damping frequency</source>
        <translation>Zweite Dämpfungsfrequenz</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="129"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../solver/model/ModelFields.cpp" line="130"/>
        <source>A second frequency with the same damping ratio (less damping between the two); 0: one frequency</source>
        <translation>Eine zweite Frequenz mit demselben Dämpfungsgrad (dazwischen weniger Dämpfung); 0: nur eine Frequenz</translation>
    </message>
    <message>
        <location filename="../gui/panels/LawFields.cpp" line="27"/>
        <source>Law</source>
        <translation>Stoffgesetz</translation>
    </message>
    <message>
        <location filename="../solver/material/ElasticLaw.cpp" line="19"/>
        <source>Linear elastic</source>
        <translation>Linear elastisch</translation>
    </message>
    <message>
        <location filename="../solver/material/ElasticLaw.cpp" line="20"/>
        <source>Stays elastic whatever the stress: a lining, a footing, a stiff inclusion</source>
        <translation>Bleibt bei jeder Spannung elastisch: eine Auskleidung, ein Fundament, ein steifer Einschluss</translation>
    </message>
</context>
<context>
    <name>PvdFile</name>
    <message>
        <location filename="../gui/results/PvdFile.cpp" line="20"/>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../gui/results/PvdFile.cpp" line="36"/>
        <source>%1 is not a valid collection: %2</source>
        <translation>%1 ist keine gültige Sammlung: %2</translation>
    </message>
    <message>
        <location filename="../gui/results/PvdFile.cpp" line="37"/>
        <source>%1 holds no collection</source>
        <translation>%1 enthält keine Sammlung</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="25"/>
        <source>Language of the program, e.g. &quot;de&quot; or &quot;en&quot; (default: $%1, else the system&apos;s).</source>
        <translation>Sprache des Programms, z. B. „de“ oder „en“ (Vorgabe: $%1, sonst die des Systems).</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="34"/>
        <source>Pre- and post-processor for elastic-plastic discontinuous deformation analysis.</source>
        <translation>Pre- und Postprozessor für die elastisch-plastische diskontinuierliche Deformationsanalyse.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="40"/>
        <source>Start the analysis once the model is open.</source>
        <translation>Die Berechnung starten, sobald das Modell geöffnet ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="43"/>
        <source>Close the program when the run ends, with the exit status of mcdda run (for demonstrations and benchmarks).</source>
        <translation>Das Programm nach der Berechnung schließen, mit dem Rückgabewert von mcdda run (für Vorführungen und Leistungsmessungen).</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="46"/>
        <source>Model file (*.json) to open.</source>
        <translation>Zu öffnende Modelldatei (*.json).</translation>
    </message>
</context>
<context>
    <name>mcdda::gui</name>
    <message>
        <location filename="../gui/results/ResultExport.cpp" line="23"/>
        <source>There is no picture to save.</source>
        <translation>Es gibt kein Bild zum Speichern.</translation>
    </message>
    <message>
        <location filename="../gui/results/ResultExport.cpp" line="28"/>
        <location filename="../gui/results/ResultExport.cpp" line="33"/>
        <location filename="../gui/results/ResultExport.cpp" line="38"/>
        <location filename="../gui/results/ResultExport.cpp" line="54"/>
        <location filename="../gui/results/ResultExport.cpp" line="67"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location filename="../gui/results/ResultExport.cpp" line="48"/>
        <location filename="../gui/results/ResultExport.cpp" line="60"/>
        <source>Cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../gui/results/ResultExport.cpp" line="79"/>
        <source>%1 lists no saved steps.</source>
        <translation>%1 führt keine gespeicherten Schritte auf.</translation>
    </message>
    <message>
        <location filename="../gui/results/ResultExport.cpp" line="84"/>
        <source>Cannot create the folder %1.</source>
        <translation>Der Ordner %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="81"/>
        <source>material &quot;%1&quot;</source>
        <translation>Material „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="91"/>
        <source>joint material &quot;%1&quot;</source>
        <translation>Trennflächenmaterial „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="94"/>
        <source>bolt &quot;%1&quot;</source>
        <translation>Anker „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="97"/>
        <source>analysis settings</source>
        <translation>Berechnungseinstellungen</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="100"/>
        <source>stage &quot;%1&quot;</source>
        <translation>Bauphase „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="102"/>
        <source>%1, analysis settings</source>
        <translation>%1, Berechnungseinstellungen</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="106"/>
        <source>region &quot;%1&quot;</source>
        <translation>Bereich „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="107"/>
        <source>%1, hole %2</source>
        <translation>%1, Öffnung %2</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="109"/>
        <source>load table &quot;%1&quot;</source>
        <translation>Lasttabelle „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="110"/>
        <location filename="../gui/session/DiagnosticText.cpp" line="113"/>
        <source>%1, point %2</source>
        <translation>%1, Punkt %2</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="112"/>
        <source>joint &quot;%1&quot;</source>
        <translation>Trennfläche „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="115"/>
        <source>joint set &quot;%1&quot;</source>
        <translation>Trennflächenschar „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="117"/>
        <source>fixed point &quot;%1&quot;</source>
        <translation>Festpunkt „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="119"/>
        <source>roller &quot;%1&quot;</source>
        <translation>Rollenlager „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="121"/>
        <source>point load &quot;%1&quot;</source>
        <translation>Punktlast „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="123"/>
        <source>edge pressure &quot;%1&quot;</source>
        <translation>Flächenlast „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="125"/>
        <source>measurement point &quot;%1&quot;</source>
        <translation>Messpunkt „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="127"/>
        <source>absorbing boundary &quot;%1&quot;</source>
        <translation>absorbierender Rand „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="129"/>
        <source>ground motion &quot;%1&quot;</source>
        <translation>Bodenbewegung „%1“</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="131"/>
        <source>mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="133"/>
        <source>in-situ stress</source>
        <translation>Primärspannung</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="135"/>
        <source>gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="137"/>
        <source>ground water</source>
        <translation>Grundwasser</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="139"/>
        <source>base motion</source>
        <translation>Fußpunktanregung</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="141"/>
        <source>seismic coefficient</source>
        <translation>Erdbebenbeiwert</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="162"/>
        <source>must lie in %1%2, %3%4</source>
        <translation>muss in %1%2; %3%4 liegen</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="166"/>
        <source>must not be negative</source>
        <translation>darf nicht negativ sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="166"/>
        <source>must be positive</source>
        <translation>muss positiv sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="168"/>
        <source>must be at least %1</source>
        <translation>muss mindestens %1 sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="168"/>
        <source>must be more than %1</source>
        <translation>muss größer als %1 sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="170"/>
        <source>must be at most %1</source>
        <translation>darf höchstens %1 sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="170"/>
        <source>must be less than %1</source>
        <translation>muss kleiner als %1 sein</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="172"/>
        <source>got %1</source>
        <translation>eingegeben %1</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="173"/>
        <source>%1; 0 = %2</source>
        <translation>%1; 0 = %2</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="174"/>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="179"/>
        <source>%1 of %2 is beyond any physical value (at most %3): check the units</source>
        <translation>%1 von %2 liegt jenseits jedes physikalischen Werts (höchstens %3): bitte die Einheiten prüfen</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="212"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="218"/>
        <source>error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="218"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/DiagnosticText.cpp" line="228"/>
        <source>Draw a region to start: choose the Region tool (Edit ▸ Draw Region) and click its corners, or type them as x, y in the coordinate field.</source>
        <translation>Zeichnen Sie zuerst einen Bereich: das Werkzeug Bereich wählen (Bearbeiten ▸ Bereich zeichnen) und seine Ecken anklicken oder sie als x; y in das Koordinatenfeld eingeben.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddHoleCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="119"/>
        <source>Add hole to region &quot;%1&quot;</source>
        <translation>Öffnung in Bereich „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddJointCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="39"/>
        <source>Add joint &quot;%1&quot;</source>
        <translation>Kluft „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddRegionCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="18"/>
        <source>Add region &quot;%1&quot;</source>
        <translation>Bereich „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::AddRollerCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="59"/>
        <source>Add roller &quot;%1&quot;</source>
        <translation>Rollenlager „%1“ hinzufügen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::BoltForm</name>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="27"/>
        <source>Bolt</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="28"/>
        <source>The rock bolt shown below; Edit ▸ Bolt draws new ones</source>
        <translation>Der unten gezeigte Felsanker; Bearbeiten ▸ Anker zeichnet neue</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="31"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="32"/>
        <source>Name of the bolt, as stages install or remove it</source>
        <translation>Name des Ankers, unter dem Bauphasen ihn einbauen oder ausbauen</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="34"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="61"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="75"/>
        <source>No bolts: Edit ▸ Bolt draws one between two anchors.</source>
        <translation>Keine Anker: Bearbeiten ▸ Anker zeichnet einen zwischen zwei Verankerungspunkten.</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="103"/>
        <source>Not applied: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="106"/>
        <source>Edit bolt &quot;%1&quot;</source>
        <translation>Anker „%1“ bearbeiten</translation>
    </message>
    <message>
        <location filename="../gui/panels/BoltForm.cpp" line="107"/>
        <source>Applied.</source>
        <translation>Übernommen.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::DisplayUnits</name>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="50"/>
        <location filename="../gui/session/DisplayUnits.cpp" line="57"/>
        <source>MPa</source>
        <translation>MPa</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="50"/>
        <location filename="../gui/session/DisplayUnits.cpp" line="57"/>
        <source>kPa</source>
        <translation>kPa</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="68"/>
        <source>kN/m³</source>
        <translation>kN/m³</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="69"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="70"/>
        <source>MN/m</source>
        <translation>MN/m</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="71"/>
        <source>kN/m</source>
        <translation>kN/m</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="72"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../gui/session/DisplayUnits.cpp" line="73"/>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::DxfImportDialog</name>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="29"/>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="37"/>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="50"/>
        <source>Import DXF</source>
        <translation>DXF importieren</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="29"/>
        <source>DXF drawings (*.dxf *.DXF)</source>
        <translation>DXF-Zeichnungen (*.dxf *.DXF)</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="38"/>
        <source>The drawing does not say its units. One drawing unit is:</source>
        <translation>Die Zeichnung nennt ihre Einheiten nicht. Eine Zeichnungseinheit ist:</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="50"/>
        <source>%1 cannot be imported:</source>
        <translation>%1 kann nicht importiert werden:</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="59"/>
        <source>Imported %1: %2</source>
        <translation>%1 importiert: %2</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/DxfImportDialog.cpp" line="61"/>
        <source>Set the materials&apos; properties (they carry defaults) and draw the supports before running.</source>
        <translation>Vor der Berechnung die Materialeigenschaften setzen (sie tragen Standardwerte) und die Lager zeichnen.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::EarthquakePanel</name>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="45"/>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="80"/>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="252"/>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="45"/>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="81"/>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="252"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="57"/>
        <source>Ground motions (acceleration records)</source>
        <translation>Bodenbewegungen (Beschleunigungszeitverläufe)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="62"/>
        <source>The model&apos;s earthquake records; the one chosen is plotted and edited below</source>
        <translation>Die Erdbebenaufzeichnungen des Modells; die gewählte wird unten dargestellt und bearbeitet</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="65"/>
        <source>Import...</source>
        <translation>Importieren...</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="67"/>
        <source>Read an acceleration record: a CSV file of time (s) and acceleration, or a PEER NGA .AT2 file (in g)</source>
        <translation>Einen Beschleunigungszeitverlauf einlesen: eine CSV-Datei mit Zeit (s) und Beschleunigung oder eine PEER-NGA-.AT2-Datei (in g)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="68"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="77"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="82"/>
        <source>Units</source>
        <translation>Einheiten</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="83"/>
        <source>Unit of the accelerations in the file: g (as in .AT2 files) or m/s²</source>
        <translation>Einheit der Beschleunigungen in der Datei: g (wie in .AT2-Dateien) oder m/s²</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="86"/>
        <source>Scale [–]</source>
        <translation>Skalierung [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="87"/>
        <source>Factor on the accelerations, e.g. to scale a record to a design peak ground acceleration</source>
        <translation>Faktor auf die Beschleunigungen, z. B. um eine Aufzeichnung auf eine Bemessungs-Bodenbeschleunigung zu skalieren</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="88"/>
        <source>Baseline correction</source>
        <translation>Basislinienkorrektur</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="91"/>
        <source>Take a linear trend off the acceleration so that the base ends at rest where it began (the integrated record does not drift)</source>
        <translation>Einen linearen Trend von der Beschleunigung abziehen, sodass die Basis dort in Ruhe endet, wo sie begann (die integrierte Aufzeichnung driftet nicht)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="97"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="108"/>
        <source>Base motion</source>
        <translation>Bewegung der Basis</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="112"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="113"/>
        <source>Rigid (supports move)</source>
        <translation>Starr (Lager bewegen sich)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="114"/>
        <source>Compliant (dashpots)</source>
        <translation>Nachgiebig (Dämpfer)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="115"/>
        <source>Shaking</source>
        <translation>Anregung</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="116"/>
        <source>Rigid: the supports move with the record and the analysis runs relative to them (a shaking table). Compliant: the segment carries dashpots and the incoming wave, so waves sent down leave the model. The base shakes the dynamic stages only</source>
        <translation>Starr: die Lager bewegen sich mit der Aufzeichnung, und die Berechnung läuft relativ zu ihnen (ein Rütteltisch). Nachgiebig: die Strecke trägt Dämpfer und die einfallende Welle, sodass nach unten laufende Wellen das Modell verlassen. Die Basis regt nur die dynamischen Bauphasen an</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="121"/>
        <source>Horizontal (x)</source>
        <translation>Horizontal (x)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="122"/>
        <source>The record of the horizontal acceleration</source>
        <translation>Die Aufzeichnung der horizontalen Beschleunigung</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="125"/>
        <source>Vertical (y)</source>
        <translation>Vertikal (y)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="126"/>
        <source>The record of the vertical acceleration</source>
        <translation>Die Aufzeichnung der vertikalen Beschleunigung</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="130"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="138"/>
        <source>From (x, y)</source>
        <translation>Von (x, y)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="139"/>
        <source>To (x, y)</source>
        <translation>Bis (x, y)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="140"/>
        <source>Draw...</source>
        <translation>Zeichnen...</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="142"/>
        <source>Click the two ends of the compliant base in the picture</source>
        <translation>Die beiden Enden der nachgiebigen Basis im Bild anklicken</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="149"/>
        <source>Seismic coefficient (pseudo-static)</source>
        <translation>Erdbebenbeiwert (pseudostatisch)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="153"/>
        <source>kh [–]</source>
        <translation>kh [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="154"/>
        <source>Horizontal seismic coefficient: every block carries kh·g per unit mass, towards +x for kh &gt; 0</source>
        <translation>Horizontaler Erdbebenbeiwert: jeder Block erhält kh·g je Masseneinheit, für kh &gt; 0 in +x-Richtung</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="157"/>
        <source>kv [–]</source>
        <translation>kv [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="158"/>
        <source>Vertical seismic coefficient: kv·g per unit mass, upwards for kv &gt; 0</source>
        <translation>Vertikaler Erdbebenbeiwert: kv·g je Masseneinheit, für kv &gt; 0 nach oben</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="162"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="164"/>
        <source>Apply the values typed in the record, base and seismic coefficient fields</source>
        <translation>Die eingegebenen Werte für Aufzeichnung, Basis und Erdbebenbeiwerte übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="215"/>
        <source>Import acceleration record</source>
        <translation>Beschleunigungszeitverlauf importieren</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="216"/>
        <source>Acceleration records (*.csv *.txt *.at2 *.AT2);;All files (*)</source>
        <translation>Beschleunigungszeitverläufe (*.csv *.txt *.at2 *.AT2);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="227"/>
        <source>The record was not imported: %1</source>
        <translation>Die Aufzeichnung wurde nicht importiert: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/panels/EarthquakePanel.cpp" line="250"/>
        <source>Imported &quot;%1&quot;: %n point(s), read in %2 (change Units if the file is in the other unit).</source>
        <translation>
            <numerusform>„%1“ importiert: %n Punkt, gelesen in %2 (Einheiten ändern, wenn die Datei in der anderen Einheit ist).</numerusform>
            <numerusform>„%1“ importiert: %n Punkte, gelesen in %2 (Einheiten ändern, wenn die Datei in der anderen Einheit ist).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="273"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="305"/>
        <source>points given in the model</source>
        <translation>Punkte im Modell angegeben</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="320"/>
        <source>Not applied: another ground motion is called &quot;%1&quot;.</source>
        <translation>Nicht übernommen: eine andere Bodenbewegung heißt „%1“.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="324"/>
        <source>Not applied: a ground motion needs a name.</source>
        <translation>Nicht übernommen: eine Bodenbewegung braucht einen Namen.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="328"/>
        <source>Not applied: the scale must not be 0.</source>
        <translation>Nicht übernommen: die Skalierung darf nicht 0 sein.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="339"/>
        <source>Applied.</source>
        <translation>Übernommen.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="360"/>
        <source>Import a ground motion first: the base moves with it.</source>
        <translation>Zuerst eine Bodenbewegung importieren: die Basis bewegt sich mit ihr.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="380"/>
        <source>The supports move with the record in the dynamic stages.</source>
        <translation>Die Lager bewegen sich in den dynamischen Bauphasen mit der Aufzeichnung.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="381"/>
        <source>The record enters through the compliant base in the dynamic stages.</source>
        <translation>Die Aufzeichnung tritt in den dynamischen Bauphasen durch die nachgiebige Basis ein.</translation>
    </message>
    <message>
        <location filename="../gui/panels/EarthquakePanel.cpp" line="382"/>
        <source>No base motion.</source>
        <translation>Keine Bewegung der Basis.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::EditingTools</name>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="129"/>
        <source>bolt %1</source>
        <translation>Anker %1</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="136"/>
        <source>Add bolt &quot;%1&quot;</source>
        <translation>Anker „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="169"/>
        <source>The water table must run from left to right: a point cannot be moved past its neighbour.</source>
        <translation>Der Grundwasserspiegel muss von links nach rechts verlaufen: Ein Punkt kann nicht über seinen Nachbarn hinaus verschoben werden.</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="190"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="194"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="204"/>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="221"/>
        <source>&amp;Select</source>
        <translation>&amp;Auswählen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="222"/>
        <source>Click an item or a vertex to select it, drag it to move it, Delete removes it; drag empty space to pan</source>
        <translation>Objekt oder Eckpunkt anklicken, um es zu wählen, ziehen, um es zu verschieben, Entf löscht es; leere Fläche ziehen verschiebt die Ansicht</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="225"/>
        <source>Draw &amp;Region</source>
        <translation>&amp;Bereich zeichnen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="226"/>
        <source>Click the corners of a new region; double-click or Enter closes it, Escape cancels</source>
        <translation>Die Ecken eines neuen Bereichs anklicken; Doppelklick oder Eingabetaste schließt ihn, Escape bricht ab</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="228"/>
        <source>Draw &amp;Joint</source>
        <translation>&amp;Kluft zeichnen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="229"/>
        <source>Click the points of a new joint; double-click or Enter finishes it, Escape cancels</source>
        <translation>Die Punkte einer neuen Kluft anklicken; Doppelklick oder Eingabetaste beendet sie, Escape bricht ab</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="232"/>
        <source>&amp;Fixed Point</source>
        <translation>&amp;Festpunkt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="233"/>
        <source>Click where the mesh is held in both directions</source>
        <translation>Dort klicken, wo das Netz in beiden Richtungen gehalten wird</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="234"/>
        <source>R&amp;oller</source>
        <translation>R&amp;ollenlager</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="235"/>
        <source>Click the two ends of a roller; the fixed directions are chosen in Tool Options</source>
        <translation>Die beiden Enden eines Rollenlagers anklicken; die gehaltenen Richtungen werden in den Werkzeugoptionen gewählt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="237"/>
        <source>Point &amp;Load</source>
        <translation>&amp;Punktlast</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="238"/>
        <source>Click where a point load acts; its force is set in Tool Options</source>
        <translation>Dort klicken, wo eine Punktlast angreift; ihre Kraft wird in den Werkzeugoptionen eingestellt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="240"/>
        <source>Edge &amp;Pressure</source>
        <translation>Kanten&amp;druck</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="241"/>
        <source>Click the two ends of a loaded edge; the pressure is set in Tool Options</source>
        <translation>Die beiden Enden einer belasteten Kante anklicken; der Druck wird in den Werkzeugoptionen eingestellt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="243"/>
        <source>&amp;Measurement Point</source>
        <translation>&amp;Messpunkt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="244"/>
        <source>Click where displacements are recorded</source>
        <translation>Dort klicken, wo Verschiebungen aufgezeichnet werden</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="246"/>
        <source>&amp;Bolt</source>
        <translation>A&amp;nker</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="247"/>
        <source>Click the two anchors of a rock bolt (EA 98 MN/m, breaking at 160 kN/m per metre of thickness; other values and the stage that installs it are set in the model file)</source>
        <translation>Die beiden Verankerungspunkte eines Felsankers anklicken (EA 98 MN/m, Bruch bei 160 kN/m je Meter Dicke; andere Werte und die Bauphase, die ihn einbaut, stehen in der Modelldatei)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="250"/>
        <source>Draw &amp;Water Table</source>
        <translation>&amp;Grundwasserspiegel zeichnen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="251"/>
        <source>Click the points of the water table (piezometric line) from left to right; double-click or Enter finishes it. It is the water of the stage chosen in the Stages dock, or of the model as drawn</source>
        <translation>Die Punkte des Grundwasserspiegels (Piezometerlinie) von links nach rechts anklicken; Doppelklick oder Eingabetaste beendet ihn. Er gilt für die im Fenster Bauphasen gewählte Bauphase oder für das Modell wie gezeichnet</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="255"/>
        <source>&amp;Absorbing Boundary</source>
        <translation>Absorbi&amp;erender Rand</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="256"/>
        <source>Click the two ends of a boundary whose dashpots let the earthquake&apos;s waves out instead of reflecting them (no support may hold it in a dynamic stage)</source>
        <translation>Die beiden Enden eines Randes anklicken, dessen Dämpfer die Wellen des Erdbebens hinauslassen, statt sie zu reflektieren (in einer dynamischen Bauphase darf ihn kein Lager halten)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="261"/>
        <source>&amp;Query Line</source>
        <translation>Abfragel&amp;inie</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="262"/>
        <source>Click the two ends of a line across the result picture: the Query dock plots the field shown along it</source>
        <translation>Die beiden Enden einer Linie über das Ergebnisbild anklicken: das Abfrage-Fenster zeigt das Feld entlang der Linie</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="266"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="271"/>
        <source>Delete the selected item or vertex</source>
        <translation>Das gewählte Objekt oder den gewählten Eckpunkt löschen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="274"/>
        <source>Add Joint Se&amp;t...</source>
        <translation>Kluft&amp;schar hinzufügen...</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="276"/>
        <source>Add a family of parallel joints</source>
        <translation>Eine Schar paralleler Klüfte hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="278"/>
        <source>Region</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="279"/>
        <source>Joint</source>
        <translation>Kluft</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="281"/>
        <source>Measurement</source>
        <translation>Messpunkt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="282"/>
        <source>Water Table</source>
        <translation>Grundwasserspiegel</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="283"/>
        <source>Absorbing</source>
        <translation>Absorbierend</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="295"/>
        <source>Tool Options</source>
        <translation>Werkzeugoptionen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="314"/>
        <source>Roller fixes</source>
        <translation>Rollenlager hält</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="317"/>
        <source>Directions a new roller holds</source>
        <translation>Richtungen, die ein neues Rollenlager hält</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="318"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="319"/>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="320"/>
        <source>x and y</source>
        <translation>x und y</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="334"/>
        <source>Load Fx</source>
        <translation>Last Fx</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="335"/>
        <location filename="../gui/tools/EditingTools.cpp" line="337"/>
        <source>kN/m</source>
        <translation>kN/m</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="335"/>
        <source>Horizontal force of a new point load</source>
        <translation>Horizontalkraft einer neuen Punktlast</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="336"/>
        <source>Fy</source>
        <translation>Fy</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="337"/>
        <source>Vertical force of a new point load</source>
        <translation>Vertikalkraft einer neuen Punktlast</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="280"/>
        <location filename="../gui/tools/EditingTools.cpp" line="339"/>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="340"/>
        <source>kPa</source>
        <translation>kPa</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="341"/>
        <source>Pressure of a new edge load (positive pushes into the material)</source>
        <translation>Druck einer neuen Flächenlast (positiv drückt in das Material)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="343"/>
        <source>γw</source>
        <translation>γw</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="344"/>
        <source>kN/m³</source>
        <translation>kN/m³</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="345"/>
        <source>Unit weight of water of a new water table (fresh water 9.81 kN/m³)</source>
        <translation>Wichte des Wassers eines neuen Grundwasserspiegels (Süßwasser 9,81 kN/m³)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="348"/>
        <source>Hole</source>
        <translation>Öffnung</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="350"/>
        <source>Draw Region cuts an opening into the region around it (or hold Shift at the first click)</source>
        <translation>Bereich zeichnen schneidet eine Öffnung in den umgebenden Bereich (oder beim ersten Klick Umschalt halten)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="353"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="356"/>
        <source>x, y</source>
        <translation>x, y</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="357"/>
        <source>Type a point as &quot;x, y&quot; (m) and press Enter to place it; Enter on an empty field finishes the shape</source>
        <translation>Punkt als „x, y“ (m) eingeben und mit Enter setzen; Enter im leeren Feld schließt die Form ab</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="380"/>
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="383"/>
        <source>Compliant Base</source>
        <translation>Nachgiebige Basis</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="384"/>
        <source>Select: no options</source>
        <translation>Auswählen: keine Optionen</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="427"/>
        <source>The hole was not added: no region contains it.</source>
        <translation>Die Öffnung wurde nicht hinzugefügt: Kein Bereich enthält sie.</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="440"/>
        <source>The water table must run from left to right: point %1 is straight above or below point %2. Draw it again.</source>
        <translation>Der Grundwasserspiegel muss von links nach rechts verlaufen: Punkt %1 liegt genau über oder unter Punkt %2. Bitte neu zeichnen.</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="442"/>
        <source>The water table must run from left to right: point %1 is left of point %2. Draw it again.</source>
        <translation>Der Grundwasserspiegel muss von links nach rechts verlaufen: Punkt %1 liegt links von Punkt %2. Bitte neu zeichnen.</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="464"/>
        <source>Type a point as &quot;x, y&quot; in metres, e.g. &quot;2.5, -1&quot; (or &quot;2,5; -1&quot;)</source>
        <translation>Einen Punkt als „x, y“ in Metern eingeben, z. B. „2.5, -1“ (oder „2,5; -1“)</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="520"/>
        <source>Import a ground motion first (Earthquake dock): the compliant base is where it enters the model.</source>
        <translation>Zuerst eine Bodenbewegung importieren (Fenster Erdbeben): die nachgiebige Basis ist die Stelle, an der sie in das Modell eintritt.</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="524"/>
        <source>Click the two ends of the compliant base</source>
        <translation>Die beiden Enden der nachgiebigen Basis anklicken</translation>
    </message>
    <message>
        <location filename="../gui/tools/EditingTools.cpp" line="537"/>
        <source>%1 was not deleted: a region or hole keeps at least three vertices.</source>
        <translation>%1 wurde nicht gelöscht: ein Bereich oder Loch behält mindestens drei Eckpunkte.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ExportMenu</name>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="14"/>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="16"/>
        <source>&amp;Picture (PNG)...</source>
        <translation>&amp;Bild (PNG)...</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="18"/>
        <source>Export picture</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="18"/>
        <source>PNG pictures (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="23"/>
        <source>Save the picture of the view as a PNG file</source>
        <translation>Das Bild der Ansicht als PNG-Datei speichern</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="24"/>
        <source>Saved &amp;Steps (PVD/VTU)...</source>
        <translation>Gespeicherte &amp;Schritte (PVD/VTU)...</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="25"/>
        <source>Export saved steps to</source>
        <translation>Gespeicherte Schritte exportieren nach</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="29"/>
        <source>Copy the run&apos;s .pvd collection and its .vtu steps to a folder</source>
        <translation>Die .pvd-Sammlung der Berechnung und ihre .vtu-Schritte in einen Ordner kopieren</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="30"/>
        <source>&amp;History (CSV)...</source>
        <translation>&amp;Verlauf (CSV)...</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="32"/>
        <source>Export history</source>
        <translation>Verlauf exportieren</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="32"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="36"/>
        <source>Copy the run&apos;s history of loads and measured displacements</source>
        <translation>Den Verlauf der Lasten und gemessenen Verschiebungen der Berechnung kopieren</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="78"/>
        <location filename="../gui/results/ExportMenu.cpp" line="111"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="86"/>
        <source>There are no saved steps yet: run the model first.</source>
        <translation>Es gibt noch keine gespeicherten Schritte: zuerst das Modell berechnen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/results/ExportMenu.cpp" line="95"/>
        <source>Copied %n file(s) to %1</source>
        <translation>
            <numerusform>%n Datei nach %1 kopiert</numerusform>
            <numerusform>%n Dateien nach %1 kopiert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/results/ExportMenu.cpp" line="103"/>
        <source>There is no history yet: run the model first.</source>
        <translation>Es gibt noch keinen Verlauf: zuerst das Modell berechnen.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::HelpMenu</name>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="26"/>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="26"/>
        <source>The document %1 is missing from this build.</source>
        <translation>Das Dokument %1 fehlt in diesem Programm.</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="31"/>
        <source>mcdda — %1</source>
        <translation>mcdda — %1</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="47"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="48"/>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="49"/>
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="53"/>
        <source>Model &amp;File Format</source>
        <translation>&amp;Modelldateiformat</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="54"/>
        <source>Model File Format</source>
        <translation>Modelldateiformat</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="56"/>
        <source>&amp;Running and Results</source>
        <translation>&amp;Berechnung und Ergebnisse</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="57"/>
        <source>Running and Results</source>
        <translation>Berechnung und Ergebnisse</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="63"/>
        <source>&amp;About mcdda</source>
        <translation>Ü&amp;ber mcdda</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="64"/>
        <source>About mcdda</source>
        <translation>Über mcdda</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/HelpMenu.cpp" line="65"/>
        <source>&lt;b&gt;mcdda %1&lt;/b&gt;&lt;p&gt;Pre- and post-processor for elastic-plastic discontinuous deformation analysis.&lt;/p&gt;&lt;p&gt;Drag with the left or middle mouse button to pan, turn the wheel to zoom, press F to fit.&lt;/p&gt;</source>
        <translation>&lt;b&gt;mcdda %1&lt;/b&gt;&lt;p&gt;Pre- und Postprozessor für die elastisch-plastische diskontinuierliche Deformationsanalyse.&lt;/p&gt;&lt;p&gt;Zum Verschieben mit der linken oder mittleren Maustaste ziehen, zum Zoomen das Mausrad drehen, zum Einpassen F drücken.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::HistoryPlot</name>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="31"/>
        <source>Measured quantity plotted: a point&apos;s displacement, velocity or acceleration (x or y), or the base&apos;s input motion</source>
        <translation>Dargestellte Messgröße: Verschiebung, Geschwindigkeit oder Beschleunigung eines Punktes (x oder y) oder die Eingangsbewegung der Basis</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="35"/>
        <source>Plotted against the load step (a static analysis), time (a dynamic one) or a load (load-settlement curve)</source>
        <translation>Aufgetragen über dem Lastschritt (statische Berechnung), der Zeit (dynamische) oder einer Last (Last-Setzungs-Kurve)</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="68"/>
        <source>Plot</source>
        <translation>Darstellen</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="70"/>
        <source>against</source>
        <translation>über</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="93"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="94"/>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="95"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="97"/>
        <source>base input %1 (%2)</source>
        <translation>Eingang der Basis %1 (%2)</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="98"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="132"/>
        <source>strength reduction factor</source>
        <translation>Festigkeitsreduktionsfaktor</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="133"/>
        <source>largest displacement (m)</source>
        <translation>größte Verschiebung (m)</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="135"/>
        <source>load step</source>
        <translation>Lastschritt</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="137"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="141"/>
        <source>load %1</source>
        <translation>Last %1</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="183"/>
        <source>No history: run the model.</source>
        <translation>Kein Verlauf: Modell berechnen.</translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="185"/>
        <source>The model has no measurement points.</source>
        <translation>Das Modell hat keine Messpunkte.</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/results/HistoryPlot.cpp" line="187"/>
        <source>%n trial(s) stood, %1 did not</source>
        <translation>
            <numerusform>%n Versuch stand, %1 nicht</numerusform>
            <numerusform>%n Versuche standen, %1 nicht</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/results/HistoryPlot.cpp" line="189"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n Schritt</numerusform>
            <numerusform>%n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/results/HistoryPlot.cpp" line="213"/>
        <source>No history yet: run the model (Run ▸ Run, F5). The displacements of its measurement points are plotted here as it runs.</source>
        <translation>Noch kein Verlauf: das Modell berechnen (Berechnung ▸ Berechnung, F5). Die Verschiebungen seiner Messpunkte werden hier während der Berechnung dargestellt.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::JointSetDialog</name>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="42"/>
        <source>Add Joint Set</source>
        <translation>Kluftschar hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="54"/>
        <source>Direction of the traces, counter-clockwise from the x axis</source>
        <translation>Richtung der Spuren, gegen den Uhrzeigersinn von der x-Achse</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="55"/>
        <source>set %1</source>
        <translation>Schar %1</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="57"/>
        <source>Name of the set (tree, messages, results)</source>
        <translation>Name der Schar (Baum, Meldungen, Ergebnisse)</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="59"/>
        <source>Apparent dip in the section: the angle of the traces from the horizontal, counter-clockwise. 0° is horizontal, 90° vertical, 30° rises to the right, 150° (or −30°) dips 30° to the right.</source>
        <translation>Scheinbares Einfallen im Schnitt: Winkel der Spuren zur Horizontalen, gegen den Uhrzeigersinn. 0° ist horizontal, 90° vertikal, 30° steigt nach rechts an, 150° (oder −30°) fällt mit 30° nach rechts ein.</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="66"/>
        <source>Normal distance between neighbouring traces</source>
        <translation>Normalabstand benachbarter Spuren</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="70"/>
        <source>Limit to a box</source>
        <translation>Auf ein Rechteck begrenzen</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="72"/>
        <source>Without a box the traces cross the whole model</source>
        <translation>Ohne Rechteck durchqueren die Spuren das ganze Modell</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="82"/>
        <source>Smallest x of the box</source>
        <translation>Kleinstes x des Rechtecks</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="83"/>
        <source>Smallest y of the box</source>
        <translation>Kleinstes y des Rechtecks</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="84"/>
        <source>Largest x of the box</source>
        <translation>Größtes x des Rechtecks</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="85"/>
        <source>Largest y of the box</source>
        <translation>Größtes y des Rechtecks</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="88"/>
        <source>(default)</source>
        <translation>(Standard)</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="91"/>
        <source>Joint material %1</source>
        <translation>Kluftmaterial %1</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="95"/>
        <source>Share of each trace that is joint; below 100 % the traces are cut into segments separated by rock bridges</source>
        <translation>Anteil jeder Spur, der Kluft ist; unter 100 % wird jede Spur in Abschnitte zerlegt, getrennt durch Felsbrücken</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="98"/>
        <source>Length of each joint segment along a trace</source>
        <translation>Länge jedes Kluftabschnitts entlang einer Spur</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="101"/>
        <source>Shift of the segment pattern from one trace to the next, in % of the period (segment plus bridge), so that the bridges do not line up</source>
        <translation>Verschiebung des Abschnittsmusters von einer Spur zur nächsten, in % der Periode (Abschnitt plus Brücke), damit die Brücken nicht in einer Linie liegen</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="112"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="113"/>
        <source>Angle from horizontal</source>
        <translation>Winkel zur Horizontalen</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="203"/>
        <source>%n trace(s) cut rock</source>
        <translation>
            <numerusform>%n Spur schneidet Fels</numerusform>
            <numerusform>%n Spuren schneiden Fels</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="115"/>
        <source>Spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="116"/>
        <source>Origin x</source>
        <translation>Ursprung x</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="117"/>
        <source>Origin y</source>
        <translation>Ursprung y</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="119"/>
        <source>x min, y min, x max, y max</source>
        <translation>x min, y min, x max, y max</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="120"/>
        <source>Joint material</source>
        <translation>Kluftmaterial</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="121"/>
        <source>Persistence</source>
        <translation>Durchtrennungsgrad</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="122"/>
        <source>Trace length</source>
        <translation>Spurlänge</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="123"/>
        <source>Stagger</source>
        <translation>Versatz</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="189"/>
        <source>The spacing must be positive.</source>
        <translation>Der Abstand muss positiv sein.</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="192"/>
        <source>The box needs x min &lt; x max and y min &lt; y max.</source>
        <translation>Das Rechteck braucht x min &lt; x max und y min &lt; y max.</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="193"/>
        <source>The persistence must be above 0 %.</source>
        <translation>Der Durchtrennungsgrad muss über 0 % liegen.</translation>
    </message>
    <message>
        <location filename="../gui/dialogs/JointSetDialog.cpp" line="195"/>
        <source>A persistence below 100 % needs a positive trace length.</source>
        <translation>Ein Durchtrennungsgrad unter 100 % braucht eine positive Spurlänge.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::LoadForm</name>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="75"/>
        <source>Load tables</source>
        <translation>Lasttabellen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="78"/>
        <source>The load table shown below: a factor against time (or step) that loads may follow</source>
        <translation>Die unten gezeigte Lasttabelle: ein Faktor über der Zeit (oder dem Schritt), dem Lasten folgen können</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="85"/>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="88"/>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="95"/>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="98"/>
        <source>Name of the load table, as loads refer to it</source>
        <translation>Name der Lasttabelle, unter dem Lasten auf sie verweisen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="101"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="103"/>
        <source>Whether the table&apos;s abscissa is the time (s) or the step number</source>
        <translation>Ob die Abszisse der Tabelle die Zeit (s) oder die Schrittnummer ist</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="105"/>
        <source>Step number</source>
        <translation>Schrittnummer</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="106"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="108"/>
        <source>Variable</source>
        <translation>Veränderliche</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="109"/>
        <source>Extrapolate (else hold the last factor)</source>
        <translation>Extrapolieren (sonst letzten Faktor halten)</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="111"/>
        <source>Beyond the last point, continue the last segment&apos;s slope</source>
        <translation>Nach dem letzten Punkt die Steigung des letzten Abschnitts fortsetzen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="121"/>
        <source>Add Row</source>
        <translation>Zeile hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="124"/>
        <source>Remove Row</source>
        <translation>Zeile entfernen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="133"/>
        <location filename="../gui/panels/LoadForm.cpp" line="172"/>
        <location filename="../gui/panels/LoadForm.cpp" line="196"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="146"/>
        <source>Point loads and edge pressures</source>
        <translation>Punktlasten und Kantendrücke</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="149"/>
        <source>The point load or edge pressure shown below</source>
        <translation>Die unten gezeigte Einzellast oder Randdruck</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="156"/>
        <source>Load</source>
        <translation>Last</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="157"/>
        <location filename="../gui/panels/LoadForm.cpp" line="160"/>
        <source>kN/m</source>
        <translation>kN/m</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="158"/>
        <source>x component of the point load, per metre out of plane</source>
        <translation>x-Komponente der Einzellast, je Meter senkrecht zur Ebene</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="159"/>
        <source>Force fx</source>
        <translation>Kraft fx</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="161"/>
        <source>y component of the point load, per metre out of plane (negative = downwards)</source>
        <translation>y-Komponente der Einzellast, je Meter senkrecht zur Ebene (negativ = nach unten)</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="162"/>
        <source>Force fy</source>
        <translation>Kraft fy</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="163"/>
        <source>kPa</source>
        <translation>kPa</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="164"/>
        <source>Normal pressure; positive pushes into the material</source>
        <translation>Normaldruck; positiv drückt in das Material</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="165"/>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="170"/>
        <source>The table whose factor multiplies the load; constant = factor 1</source>
        <translation>Die Tabelle, deren Faktor die Last multipliziert; konstant = Faktor 1</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="171"/>
        <source>Load table</source>
        <translation>Lasttabelle</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="185"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="187"/>
        <location filename="../gui/panels/LoadForm.cpp" line="190"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="188"/>
        <source>x component of the acceleration of gravity</source>
        <translation>x-Komponente der Erdbeschleunigung</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="189"/>
        <source>gx</source>
        <translation>gx</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="191"/>
        <source>y component of the acceleration of gravity (−9.81 m/s²: standard)</source>
        <translation>y-Komponente der Erdbeschleunigung (−9,81 m/s²: Standard)</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="192"/>
        <source>gy</source>
        <translation>gy</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="193"/>
        <source>Standard (0, −9.81)</source>
        <translation>Standard (0, −9,81)</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="215"/>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="215"/>
        <source>Step [–]</source>
        <translation>Schritt [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="215"/>
        <source>Factor [–]</source>
        <translation>Faktor [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="227"/>
        <source>constant</source>
        <translation>konstant</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="229"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="236"/>
        <source>Point load &quot;%1&quot;</source>
        <translation>Punktlast „%1“</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="237"/>
        <source>Edge pressure &quot;%1&quot;</source>
        <translation>Kantendruck „%1“</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="370"/>
        <source>Not applied: row %1: %2 &quot;%3&quot; is not a number</source>
        <translation>Nicht übernommen: Zeile %1: %2 „%3“ ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="372"/>
        <source>abscissa</source>
        <translation>Abszisse</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="372"/>
        <source>factor</source>
        <translation>Faktor</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="384"/>
        <location filename="../gui/panels/LoadForm.cpp" line="493"/>
        <location filename="../gui/panels/LoadForm.cpp" line="509"/>
        <source>Not applied: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="390"/>
        <source>Change load table &quot;%1&quot;</source>
        <translation>Lasttabelle „%1“ ändern</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="391"/>
        <location filename="../gui/panels/LoadForm.cpp" line="496"/>
        <location filename="../gui/panels/LoadForm.cpp" line="514"/>
        <source>Applied.</source>
        <translation>Übernommen.</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="411"/>
        <source>Not added: %1</source>
        <translation>Nicht hinzugefügt: %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="416"/>
        <source>Add load table &quot;%1&quot;</source>
        <translation>Lasttabelle „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="418"/>
        <source>Added &quot;%1&quot;.</source>
        <translation>„%1“ hinzugefügt.</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="431"/>
        <source>Not deleted: load table &quot;%1&quot; is used by point load &quot;%2&quot;</source>
        <translation>Nicht gelöscht: Lasttabelle „%1“ wird von Punktlast „%2“ verwendet</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="438"/>
        <source>Not deleted: load table &quot;%1&quot; is used by edge pressure &quot;%2&quot;</source>
        <translation>Nicht gelöscht: Lasttabelle „%1“ wird von Kantendruck „%2“ verwendet</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="449"/>
        <source>Delete load table &quot;%1&quot;</source>
        <translation>Lasttabelle „%1“ löschen</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="450"/>
        <source>Deleted &quot;%1&quot;.</source>
        <translation>„%1“ gelöscht.</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="477"/>
        <source>Change point load &quot;%1&quot;</source>
        <translation>Punktlast „%1“ ändern</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="490"/>
        <source>Change edge pressure &quot;%1&quot;</source>
        <translation>Kantendruck „%1“ ändern</translation>
    </message>
    <message>
        <location filename="../gui/panels/LoadForm.cpp" line="513"/>
        <source>Change gravity</source>
        <translation>Schwerkraft ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::MainWindow</name>
    <message>
        <location filename="../gui/MainWindow.cpp" line="98"/>
        <source>mcdda</source>
        <translation>mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="126"/>
        <source>Query</source>
        <translation>Abfrage</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="139"/>
        <source>Stages</source>
        <translation>Bauphasen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="143"/>
        <source>Earthquake</source>
        <translation>Erdbeben</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="168"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="169"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="172"/>
        <source>Start an empty model</source>
        <translation>Ein leeres Modell beginnen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="173"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="176"/>
        <source>Open a model file (*.json)</source>
        <translation>Eine Modelldatei öffnen (*.json)</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="177"/>
        <source>&amp;Reload</source>
        <translation>Neu &amp;laden</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="180"/>
        <source>Read the model file again, e.g. after editing it</source>
        <translation>Die Modelldatei erneut lesen, z. B. nachdem sie bearbeitet wurde</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="188"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="192"/>
        <source>Write the model to its file</source>
        <translation>Das Modell in seine Datei schreiben</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="193"/>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="196"/>
        <source>Write the model to a new file</source>
        <translation>Das Modell in eine neue Datei schreiben</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="211"/>
        <source>&amp;Import DXF...</source>
        <translation>DXF &amp;importieren...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="213"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="215"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="119"/>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="326"/>
        <source>joint</source>
        <translation>Kluft</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="80"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="306"/>
        <source>%1[*] - mcdda</source>
        <translation>%1[*] - mcdda</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="313"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="314"/>
        <source>The model has been modified. Save the changes?</source>
        <translation>Das Modell wurde geändert. Sollen die Änderungen gespeichert werden?</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="326"/>
        <source>rock</source>
        <translation>Fels</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="328"/>
        <source>New model: draw regions with Edit ▸ Draw Region.</source>
        <translation>Neues Modell: Bereiche über Bearbeiten ▸ Bereich zeichnen anlegen.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="349"/>
        <source>Save model</source>
        <translation>Modell speichern</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="349"/>
        <source>Model files (*.json)</source>
        <translation>Modelldateien (*.json)</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="365"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="84"/>
        <source>Pre-processing...</source>
        <translation>Vorverarbeitung...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="114"/>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="122"/>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="136"/>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="398"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="426"/>
        <source>Open model</source>
        <translation>Modell öffnen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="427"/>
        <source>Model files (*.json);;All files (*)</source>
        <translation>Modelldateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="480"/>
        <source>The run was stopped: another model was opened.</source>
        <translation>Die Berechnung wurde angehalten: ein anderes Modell wurde geöffnet.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="481"/>
        <source>The run was stopped: the model was edited.</source>
        <translation>Die Berechnung wurde angehalten: das Modell wurde geändert.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="528"/>
        <source>Folder for the results</source>
        <translation>Ordner für die Ergebnisse</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="577"/>
        <source>Run an unsaved model</source>
        <translation>Nicht gespeichertes Modell berechnen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="578"/>
        <source>The model has not been saved yet. Where should its results go?</source>
        <translation>Das Modell wurde noch nicht gespeichert. Wohin sollen seine Ergebnisse?</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="579"/>
        <source>Save the model first to keep its results in a folder beside it (&lt;model&gt;-results), or run it now with the results in a new temporary folder.</source>
        <translation>Das Modell zuerst speichern, um seine Ergebnisse in einem Ordner daneben zu behalten (&lt;Modell&gt;-results), oder es jetzt berechnen, mit den Ergebnissen in einem neuen temporären Ordner.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="581"/>
        <source>Save and Run...</source>
        <translation>Speichern und berechnen...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="582"/>
        <source>Run in a Temporary Folder</source>
        <translation>In temporärem Ordner berechnen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="590"/>
        <source>No folder for the results: %1</source>
        <translation>Kein Ordner für die Ergebnisse: %1</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="596"/>
        <source>The model is not saved: its results go to the new folder %1 (File ▸ Save As keeps the model; its next run writes beside it).</source>
        <translation>Das Modell ist nicht gespeichert: seine Ergebnisse kommen in den neuen Ordner %1 (Datei ▸ Speichern unter behält das Modell; seine nächste Berechnung schreibt daneben).</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/MainWindow.cpp" line="628"/>
        <source>Run started: %n step(s); results in %1</source>
        <translation>
            <numerusform>Berechnung gestartet: %n Schritt; Ergebnisse in %1</numerusform>
            <numerusform>Berechnung gestartet: %n Schritte; Ergebnisse in %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="664"/>
        <source>Run resumed.</source>
        <translation>Berechnung fortgesetzt.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="664"/>
        <source>Run paused.</source>
        <translation>Berechnung unterbrochen.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="611"/>
        <source>Stopping the run...</source>
        <translation>Berechnung wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="692"/>
        <source>Strength reduction completed: %1.</source>
        <translation>Festigkeitsreduktion abgeschlossen: %1.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="700"/>
        <source>Results in %1</source>
        <translation>Ergebnisse in %1</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="719"/>
        <source>Collapse</source>
        <translation>Kollaps</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="719"/>
        <source>Run failed</source>
        <translation>Berechnung fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="720"/>
        <source>The results up to the last accepted step are kept in %1.</source>
        <translation>Die Ergebnisse bis zum letzten angenommenen Schritt bleiben in %1 erhalten.</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="148"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="289"/>
        <source>Selected %1: drag to move, Delete removes</source>
        <translation>%1 gewählt: ziehen verschiebt, Entf löscht</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="443"/>
        <source>Reading and meshing %1...</source>
        <translation>%1 wird gelesen und vernetzt...</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="512"/>
        <source>Model not usable</source>
        <translation>Modell nicht verwendbar</translation>
    </message>
    <message>
        <location filename="../gui/MainWindow.cpp" line="513"/>
        <source>%1 could not be pre-processed.</source>
        <translation>%1 konnte nicht vorverarbeitet werden.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::MeshForm</name>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="55"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="57"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="58"/>
        <source>Target longest edge of a triangle; 0 = automatic (1/20 of the model&apos;s diagonal)</source>
        <translation>Angestrebte längste Dreieckskante; 0 = automatisch (1/20 der Modelldiagonale)</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="59"/>
        <source>Element size</source>
        <translation>Elementgröße</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="60"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="61"/>
        <source>Smallest angle a triangle may have, (0°, 34°]</source>
        <translation>Kleinster zulässiger Dreieckswinkel, (0°, 34°]</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="62"/>
        <source>Minimum angle</source>
        <translation>Mindestwinkel</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="65"/>
        <source>Growth of the size away from a local refinement: size = local size + grading × (distance − radius)</source>
        <translation>Zunahme der Größe außerhalb einer lokalen Verfeinerung: Größe = lokale Größe + Gradierung × (Abstand − Radius)</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="67"/>
        <source>Grading [–]</source>
        <translation>Gradierung [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="68"/>
        <source>elements</source>
        <translation>Elemente</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="71"/>
        <source>The mesher refuses a model whose size field asks for more triangles</source>
        <translation>Der Vernetzer lehnt ein Modell ab, dessen Größenfeld mehr Dreiecke verlangt</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="72"/>
        <source>Element limit</source>
        <translation>Elementgrenze</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="76"/>
        <source>At [m]</source>
        <translation>Bei [m]</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="76"/>
        <source>Size [m]</source>
        <translation>Größe [m]</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="76"/>
        <source>Radius [m]</source>
        <translation>Radius [m]</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="82"/>
        <source>Local refinements</source>
        <translation>Lokale Verfeinerungen</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="85"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="112"/>
        <source>(%1, %2)</source>
        <translation>(%1, %2)</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="113"/>
        <source>(%1, %2) – (%3, %4)</source>
        <translation>(%1, %2) – (%3, %4)</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="142"/>
        <source>Not applied: local refinement %1: %2 &quot;%3&quot; is not a number</source>
        <translation>Nicht übernommen: lokale Verfeinerung %1: %2 „%3“ ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="144"/>
        <source>size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="144"/>
        <source>radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="155"/>
        <source>Not applied: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="159"/>
        <source>Change mesh controls</source>
        <translation>Vernetzungsvorgaben ändern</translation>
    </message>
    <message>
        <location filename="../gui/panels/MeshForm.cpp" line="160"/>
        <source>Applied.</source>
        <translation>Übernommen.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::MessageLog</name>
    <message>
        <location filename="../gui/widgets/MessageLog.cpp" line="12"/>
        <source>Messages about the model appear here.</source>
        <translation>Meldungen zum Modell erscheinen hier.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ModelDocument</name>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="53"/>
        <source>The model has no file yet; choose one with Save As.</source>
        <translation>Das Modell hat noch keine Datei; wählen Sie eine mit „Speichern unter“.</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="76"/>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="129"/>
        <source>Add fixed point &quot;%1&quot;</source>
        <translation>Festpunkt „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="136"/>
        <source>Add point load &quot;%1&quot;</source>
        <translation>Punktlast „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="143"/>
        <source>Add edge pressure &quot;%1&quot;</source>
        <translation>Kantendruck „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="150"/>
        <source>Add measurement point &quot;%1&quot;</source>
        <translation>Messpunkt „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="171"/>
        <source>Add joint set &quot;%1&quot;</source>
        <translation>Kluftschar „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="178"/>
        <source>Add material &quot;%1&quot;</source>
        <translation>Material „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="186"/>
        <source>Add joint material &quot;%1&quot;</source>
        <translation>Kluftmaterial „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="195"/>
        <source>Assign a material to %1</source>
        <translation>%1 ein Material zuweisen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="203"/>
        <source>Assign a joint material to %1</source>
        <translation>%1 ein Kluftmaterial zuweisen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="210"/>
        <source>Set the water table</source>
        <translation>Grundwasserspiegel festlegen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="210"/>
        <source>Make the ground dry</source>
        <translation>Boden trockenlegen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="216"/>
        <source>Stage &quot;%1&quot;: water as in the stage before</source>
        <translation>Bauphase „%1“: Grundwasser wie in der Bauphase davor</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="217"/>
        <source>Stage &quot;%1&quot;: set the water table</source>
        <translation>Bauphase „%1“: Grundwasserspiegel festlegen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="218"/>
        <source>Stage &quot;%1&quot;: make the ground dry</source>
        <translation>Bauphase „%1“: Boden trockenlegen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="227"/>
        <source>Add ground motion &quot;%1&quot;</source>
        <translation>Bodenbewegung „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="237"/>
        <source>Change ground motion &quot;%1&quot;</source>
        <translation>Bodenbewegung „%1“ ändern</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="251"/>
        <source>Remove ground motion &quot;%1&quot;</source>
        <translation>Bodenbewegung „%1“ entfernen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="255"/>
        <source>Remove the base motion</source>
        <translation>Bewegung der Basis entfernen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="256"/>
        <source>Shake a rigid base</source>
        <translation>Starre Basis anregen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="257"/>
        <source>Shake a compliant base</source>
        <translation>Nachgiebige Basis anregen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="264"/>
        <source>Add absorbing boundary &quot;%1&quot;</source>
        <translation>Absorbierenden Rand „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="272"/>
        <source>Set the seismic coefficient</source>
        <translation>Erdbebenbeiwert setzen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="279"/>
        <source>Stage &quot;%1&quot;: set the seismic coefficient</source>
        <translation>Bauphase „%1“: Erdbebenbeiwert setzen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="291"/>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="299"/>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="312"/>
        <source>region %1</source>
        <translation>Bereich %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="313"/>
        <source>joint %1</source>
        <translation>Kluft %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="314"/>
        <source>fixed point %1</source>
        <translation>Festpunkt %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="315"/>
        <source>roller %1</source>
        <translation>Rollenlager %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="316"/>
        <source>load %1</source>
        <translation>Last %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="317"/>
        <source>pressure %1</source>
        <translation>Kantendruck %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="318"/>
        <source>point %1</source>
        <translation>Punkt %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="320"/>
        <source>absorbing boundary %1</source>
        <translation>absorbierender Rand %1</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="322"/>
        <source>the compliant base</source>
        <translation>die nachgiebige Basis</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="324"/>
        <source>the water table</source>
        <translation>Grundwasserspiegel</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="325"/>
        <source>the water table of stage &quot;%1&quot;</source>
        <translation>Grundwasserspiegel der Bauphase „%1“</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="330"/>
        <source>hole %1 of %2</source>
        <translation>Loch %1 von %2</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="331"/>
        <source>vertex %1 of %2</source>
        <translation>Eckpunkt %1 von %2</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="344"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../gui/document/ModelDocument.cpp" line="346"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ModelTree</name>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="42"/>
        <source>pressure %1 MPa</source>
        <translation>Druck %1 MPa</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="43"/>
        <source>pressure %1 kPa</source>
        <translation>Druck %1 kPa</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="72"/>
        <source>Item</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="72"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="103"/>
        <source>Regions</source>
        <translation>Bereiche</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="108"/>
        <location filename="../gui/widgets/ModelTree.cpp" line="125"/>
        <source>no material</source>
        <translation>kein Material</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="109"/>
        <source>region %1</source>
        <translation>Bereich %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="110"/>
        <source>%1, %n vertices</source>
        <translation>
            <numerusform>%1, %n Eckpunkt</numerusform>
            <numerusform>%1, %n Eckpunkte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="113"/>
        <source>hole %1</source>
        <translation>Loch %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="113"/>
        <source>%n vertices</source>
        <translation>
            <numerusform>%n Eckpunkt</numerusform>
            <numerusform>%n Eckpunkte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="120"/>
        <source>Blocks</source>
        <translation>Blöcke</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="128"/>
        <source>block %1</source>
        <translation>Block %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="129"/>
        <source>%1, %2 m², %n elements</source>
        <translation>
            <numerusform>%1, %2 m², %n Element</numerusform>
            <numerusform>%1, %2 m², %n Elemente</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="133"/>
        <source>Joints</source>
        <translation>Klüfte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="134"/>
        <source>Explicit</source>
        <translation>Einzelklüfte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="138"/>
        <source>spacing %1 m</source>
        <translation>Abstand %1 m</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="140"/>
        <source>, persistence %1 %, joints %2 m long</source>
        <translation>, Durchtrennungsgrad %1 %, Klüfte %2 m lang</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="141"/>
        <source>Set %1</source>
        <translation>Kluftschar %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="150"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="151"/>
        <source>joint %1</source>
        <translation>Kluft %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="156"/>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="157"/>
        <source>rock/soil</source>
        <translation>Fels/Boden</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="158"/>
        <source>joint</source>
        <translation>Kluft</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="159"/>
        <source>Supports</source>
        <translation>Auflager</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="161"/>
        <source>fixed point %1</source>
        <translation>Festpunkt %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="165"/>
        <source>roller %1 to %2</source>
        <translation>Rollenlager %1 bis %2</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="170"/>
        <source>Earthquake</source>
        <translation>Erdbeben</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="172"/>
        <source>record of %n point(s)</source>
        <translation>
            <numerusform>Aufzeichnung mit %n Punkt</numerusform>
            <numerusform>Aufzeichnung mit %n Punkten</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="173"/>
        <source>record %1</source>
        <translation>Aufzeichnung %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="174"/>
        <source>rigid base</source>
        <translation>starre Basis</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="174"/>
        <source>every support moves</source>
        <translation>alle Lager bewegen sich</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="176"/>
        <location filename="../gui/widgets/ModelTree.cpp" line="180"/>
        <source>dashpots %1 to %2</source>
        <translation>Dämpfer %1 bis %2</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="176"/>
        <source>compliant base</source>
        <translation>nachgiebige Basis</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="183"/>
        <source>Loads</source>
        <translation>Lasten</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="185"/>
        <source>point load at %1</source>
        <translation>Punktlast bei %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="191"/>
        <source>Measurement points</source>
        <translation>Messpunkte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="196"/>
        <source>Bolts</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="198"/>
        <source>%1 to %2, EA %3 MN/m</source>
        <translation>%1 bis %2, EA %3 MN/m</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="202"/>
        <source>Stages</source>
        <translation>Bauphasen</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="216"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n Schritt</numerusform>
            <numerusform>%n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="217"/>
        <source>excavates %1</source>
        <translation>Aushub: %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="218"/>
        <source>builds %1</source>
        <translation>Einbau von Bereichen: %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="219"/>
        <source>installs %1</source>
        <translation>Stützmittel einbauen: %1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="220"/>
        <source>removes %1</source>
        <translation>Stützmittel ausbauen: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ModelTree.cpp" line="221"/>
        <source>%n material change(s)</source>
        <translation>
            <numerusform>%n Materialänderung</numerusform>
            <numerusform>%n Materialänderungen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="223"/>
        <source>water table of %1 points</source>
        <translation>Grundwasserspiegel mit %1 Punkten</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="224"/>
        <source>dry</source>
        <translation>trocken</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="225"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="230"/>
        <source>Ground water</source>
        <translation>Grundwasser</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="231"/>
        <source>water table</source>
        <translation>Grundwasserspiegel</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ModelTree.cpp" line="232"/>
        <source>%1 points, γw %2 kN/m³</source>
        <translation>%1 Punkte, γw %2 kN/m³</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::PropertyEditor</name>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="88"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="132"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="89"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="181"/>
        <source>Joint material</source>
        <translation>Kluftmaterial</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="90"/>
        <source>Analysis</source>
        <translation>Berechnung</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="91"/>
        <source>In-situ stress</source>
        <translation>Primärspannung</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="94"/>
        <source>Loads</source>
        <translation>Lasten</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="96"/>
        <source>Bolts</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="99"/>
        <source>Mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="133"/>
        <source>The material shown below; Assign to Selection gives it to the selected region</source>
        <translation>Das unten gezeigte Material; „Auswahl zuweisen“ gibt es dem gewählten Bereich</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="134"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="183"/>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="136"/>
        <source>Add a material (a copy of the one shown)</source>
        <translation>Ein Material hinzufügen (eine Kopie des angezeigten)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="138"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="187"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="490"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="492"/>
        <source>Assign to Selection</source>
        <translation>Der Auswahl zuweisen</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="140"/>
        <source>The region selected in the view or the Model tree is made of this material</source>
        <translation>Der in der Ansicht oder im Modellbaum gewählte Bereich erhält dieses Material</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="145"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="194"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="146"/>
        <source>Name of the material, as the tree and the legend show it</source>
        <translation>Name des Materials, wie ihn Baum und Legende zeigen</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="156"/>
        <source>Whether a strength reduction divides this material&apos;s strength; off for a footing or a lining that must not fail in the search</source>
        <translation>Ob eine Festigkeitsreduktion die Festigkeit dieses Materials teilt; aus für ein Fundament oder eine Auskleidung, die bei der Suche nicht versagen darf</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="227"/>
        <source>Number of load steps (a static analysis) or time steps (a dynamic one); the loads follow their tables over the steps</source>
        <translation>Anzahl der Lastschritte (statische Berechnung) oder Zeitschritte (dynamische); die Lasten folgen über die Schritte ihren Tabellen</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="287"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="290"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="293"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="301"/>
        <source>kPa</source>
        <translation>kPa</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="153"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="198"/>
        <source>Reduced in a strength reduction</source>
        <translation>In der Festigkeitsreduktion abgemindert</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="157"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="202"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="260"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="311"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="182"/>
        <source>The joint material shown below; Assign to Selection gives it to the selected joint</source>
        <translation>Das unten gezeigte Kluftmaterial; „Auswahl zuweisen“ gibt es der gewählten Kluft</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="185"/>
        <source>Add a joint material (a copy of the one shown)</source>
        <translation>Ein Kluftmaterial hinzufügen (eine Kopie des angezeigten)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="189"/>
        <source>The joint selected in the view or the Model tree gets this joint material</source>
        <translation>Die in der Ansicht oder im Modellbaum gewählte Kluft erhält dieses Kluftmaterial</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="195"/>
        <source>Name of the joint material</source>
        <translation>Name des Kluftmaterials</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="201"/>
        <source>Whether a strength reduction divides this joint material&apos;s cohesion, tan φj and tensile strength</source>
        <translation>Ob eine Festigkeitsreduktion Kohäsion, tan φj und Zugfestigkeit dieses Kluftmaterials teilt</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="220"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="282"/>
        <source>Type</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="235"/>
        <source> steps</source>
        <translation> Schritte</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="236"/>
        <source>Save every</source>
        <translation>Speichern alle</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="237"/>
        <source>Every how many steps the results are written (the last step always is)</source>
        <translation>Alle wie viele Schritte die Ergebnisse geschrieben werden (der letzte Schritt immer)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="238"/>
        <source>Plasticity</source>
        <translation>Plastizität</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="241"/>
        <source>Off: every material stays elastic (a quick elastic check of a plastic model)</source>
        <translation>Aus: jedes Material bleibt elastisch (eine schnelle elastische Kontrolle eines plastischen Modells)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="244"/>
        <source>Davis (associated, strength lowered)</source>
        <translation>Davis (assoziiert, Festigkeit abgemindert)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="246"/>
        <source>Direct (ψ as given)</source>
        <translation>Direkt (ψ wie angegeben)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="247"/>
        <source>Non-associated flow</source>
        <translation>Nicht-assoziiertes Fließen</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="248"/>
        <source>Strength reduction of materials whose dilation angle is below their friction angle. Davis: each trial&apos;s reduced c and tan φ are lowered by β = cos ψ cos φ / (1 − sin ψ sin φ) and solved with associated flow: a factor that converges with the mesh. Direct: ψ as given; the non-associated law has no unique limit load and its factor may depend on the mesh and the iteration where much of the ground yields</source>
        <translation>Festigkeitsreduktion von Materialien, deren Dilatanzwinkel unter dem Reibungswinkel liegt. Davis: die abgeminderten c und tan φ jedes Versuchs werden nochmals mit β = cos ψ cos φ / (1 − sin ψ sin φ) abgemindert und mit assoziiertem Fließen gerechnet: ein Faktor, der mit dem Netz konvergiert. Direkt: ψ wie angegeben; das nicht-assoziierte Gesetz hat keine eindeutige Traglast, und sein Faktor kann vom Netz und von der Iteration abhängen, wo ein großer Teil des Bodens plastifiziert</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="278"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="279"/>
        <source>Uniform</source>
        <translation>Gleichförmig</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="280"/>
        <source>From gravity</source>
        <translation>Aus Eigengewicht</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="283"/>
        <source>In-situ stress before the first step: none, uniform (the values below) or from gravity (overburden and K0)</source>
        <translation>Primärspannung vor dem ersten Schritt: keine, gleichförmig (die Werte unten) oder aus der Schwerkraft (Überlagerung und K0)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="284"/>
        <source>Stresses: compression positive.</source>
        <translation>Spannungen: Druck positiv.</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="288"/>
        <source>σxx</source>
        <translation>σxx</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="289"/>
        <source>Horizontal in-situ stress, compression positive</source>
        <translation>Horizontale Primärspannung, Druck positiv</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="291"/>
        <source>σyy</source>
        <translation>σyy</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="292"/>
        <source>Vertical in-situ stress, compression positive</source>
        <translation>Vertikale Primärspannung, Druck positiv</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="294"/>
        <source>τxy</source>
        <translation>τxy</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="295"/>
        <source>In-situ shear stress</source>
        <translation>Primäre Schubspannung</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="296"/>
        <source>σzz given (else ν(σxx + σyy))</source>
        <translation>σzz vorgegeben (sonst ν(σxx + σyy))</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="300"/>
        <source>Give the out-of-plane stress σzz yourself; else it follows from plane strain, ν(σxx + σyy)</source>
        <translation>Die Spannung σzz senkrecht zur Ebene selbst angeben; sonst folgt sie aus dem ebenen Verzerrungszustand, ν(σxx + σyy)</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="302"/>
        <source>σzz</source>
        <translation>σzz</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="303"/>
        <source>Out-of-plane in-situ stress, compression positive</source>
        <translation>Primärspannung senkrecht zur Ebene, Druck positiv</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="304"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="305"/>
        <source>Ground surface y</source>
        <translation>Geländeoberfläche y</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="306"/>
        <source>Height of the ground surface: the overburden of a point is the rock above it up to here</source>
        <translation>Höhe der Geländeoberfläche: die Überlagerung eines Punktes ist das Gestein darüber bis hierher</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="309"/>
        <source>K0 = σh/σv [–]</source>
        <translation>K0 = σh/σv [–]</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="310"/>
        <source>Ratio of horizontal to vertical in-situ stress, ≥ 0</source>
        <translation>Verhältnis von horizontaler zu vertikaler Primärspannung, ≥ 0</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="344"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="349"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="490"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="492"/>
        <source>Assign to %1</source>
        <translation>Zuweisen an %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="511"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="528"/>
        <source>Added &quot;%1&quot;.</source>
        <translation>„%1“ hinzugefügt.</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="539"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="549"/>
        <source>Assigned to %1.</source>
        <translation>Zugewiesen an %1.</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="569"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="592"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="617"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="644"/>
        <source>Not applied: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/PropertyEditor.cpp" line="573"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="596"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="621"/>
        <location filename="../gui/panels/PropertyEditor.cpp" line="648"/>
        <source>Applied.</source>
        <translation>Übernommen.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::QueryLine</name>
    <message>
        <location filename="../gui/results/QueryLine.cpp" line="32"/>
        <location filename="../gui/results/QueryLine.cpp" line="43"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::QueryPlot</name>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="97"/>
        <source>Draw a line with Edit ▸ Query Line to plot the field shown along it.</source>
        <translation>Mit Bearbeiten ▸ Abfragelinie eine Linie zeichnen, um das gezeigte Feld entlang der Linie darzustellen.</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="32"/>
        <source>Export CSV...</source>
        <translation>CSV exportieren...</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="34"/>
        <source>Save distance, x, y and value of the points on the mesh as CSV</source>
        <translation>Abstand, x, y und Wert der Punkte auf dem Netz als CSV speichern</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="37"/>
        <source>Export query line</source>
        <translation>Abfragelinie exportieren</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="38"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="40"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="46"/>
        <source>distance along the line (m)</source>
        <translation>Abstand entlang der Linie (m)</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="151"/>
        <source>Query line from (%1, %2) to (%3, %4) m</source>
        <translation>Abfragelinie von (%1, %2) bis (%3, %4) m</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="156"/>
        <source>The picture shows no result: run the model or choose a saved step.</source>
        <translation>Das Bild zeigt kein Ergebnis: das Modell berechnen oder einen gespeicherten Schritt wählen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/results/QueryPlot.cpp" line="158"/>
        <source>%1 from (%2, %3) to (%4, %5) m: %n point(s) on the mesh</source>
        <translation>
            <numerusform>%1 von (%2, %3) bis (%4, %5) m: %n Punkt auf dem Netz</numerusform>
            <numerusform>%1 von (%2, %3) bis (%4, %5) m: %n Punkte auf dem Netz</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="167"/>
        <source>The line does not cross the mesh.</source>
        <translation>Die Linie kreuzt das Netz nicht.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::RecentFilesMenu</name>
    <message>
        <location filename="../gui/widgets/RecentFilesMenu.cpp" line="15"/>
        <source>Recent &amp;Files</source>
        <translation>&amp;Zuletzt geöffnete Dateien</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RecentFilesMenu.cpp" line="40"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::RecordPlot</name>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="41"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="76"/>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="76"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="95"/>
        <source>acceleration (%1)</source>
        <translation>Beschleunigung (%1)</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="98"/>
        <source>No record chosen.</source>
        <translation>Keine Aufzeichnung gewählt.</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="100"/>
        <source>The record has no usable points (at least two, times increasing).</source>
        <translation>Die Aufzeichnung hat keine brauchbaren Punkte (mindestens zwei, mit steigenden Zeiten).</translation>
    </message>
    <message>
        <location filename="../gui/results/RecordPlot.cpp" line="102"/>
        <source>Peak %1 %2 at %3 s, duration %4 s</source>
        <translation>Spitzenwert %1 %2 bei %3 s, Dauer %4 s</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ResultToolBar</name>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="64"/>
        <source>Results</source>
        <translation>Ergebnisse</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="68"/>
        <source>Field shown for results</source>
        <translation>Angezeigtes Ergebnisfeld</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="70"/>
        <source>Displacement |u|</source>
        <translation>Verschiebung |u|</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="71"/>
        <source>Displacement ux</source>
        <translation>Verschiebung ux</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="72"/>
        <source>Displacement uy</source>
        <translation>Verschiebung uy</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="73"/>
        <source>Stress σxx</source>
        <translation>Spannung σxx</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="74"/>
        <source>Stress σyy</source>
        <translation>Spannung σyy</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="75"/>
        <source>Stress τxy</source>
        <translation>Spannung τxy</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="76"/>
        <source>Principal stress σ1</source>
        <translation>Hauptspannung σ1</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="77"/>
        <source>Principal stress σ3</source>
        <translation>Hauptspannung σ3</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="78"/>
        <source>Plastic state</source>
        <translation>Plastischer Zustand</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="79"/>
        <source>Plastic strain</source>
        <translation>Plastische Dehnung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="82"/>
        <source>Mechanism: plastic strain increment</source>
        <translation>Mechanismus: plastisches Dehnungsinkrement</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="83"/>
        <source>Mechanism: displacement increment</source>
        <translation>Mechanismus: Verschiebungsinkrement</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="90"/>
        <source>compression +</source>
        <translation>Druck +</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="91"/>
        <source>tension +</source>
        <translation>Zug +</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="92"/>
        <source>Sign of the stresses shown. Compression positive (as RS2, PLAXIS and UDEC): σ1 is the major compressive stress, σ1 ≥ σ3. Tension positive: the result files&apos; convention.</source>
        <translation>Vorzeichen der gezeigten Spannungen. Druck positiv (wie RS2, PLAXIS und UDEC): σ1 ist die größte Druckspannung, σ1 ≥ σ3. Zug positiv: die Konvention der Ergebnisdateien.</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="99"/>
        <source>Total stress</source>
        <translation>Totale Spannung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="100"/>
        <source>Effective stress</source>
        <translation>Effektive Spannung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="101"/>
        <source>Stresses of a run with ground water: total stress σ, or effective stress σ′ (the total stress less the pore pressure: what the rock or soil yields on). τxy is the same in both. Without water the stresses are total.</source>
        <translation>Spannungen einer Berechnung mit Grundwasser: totale Spannung σ oder effektive Spannung σ′ (die totale Spannung abzüglich des Porenwasserdrucks: maßgebend für das Fließen von Fels und Boden). τxy ist in beiden gleich. Ohne Wasser sind die Spannungen total.</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="108"/>
        <source>Deformation ×</source>
        <translation>Verformung ×</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="111"/>
        <source>Scale factor of the drawn displacements: 0 = undeformed; one step below 0 = auto, the largest displacement drawn as 5 % of the model&apos;s size</source>
        <translation>Überhöhung der gezeichneten Verschiebungen: 0 = unverformt; eine Stufe unter 0 = auto, die größte Verschiebung als 5 % der Modellgröße gezeichnet</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="114"/>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="188"/>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="125"/>
        <source>Contacts</source>
        <translation>Kontakte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="129"/>
        <source>Draw the contact forces (lines along the force, the largest 6 % of the model long), joint slip and opening, and the bolts of the saved step shown</source>
        <translation>Kontaktkräfte (Linien in Kraftrichtung, die größte 6 % der Modellgröße lang), Kluftgleiten und -öffnung und die Anker des gezeigten gespeicherten Schritts zeichnen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="136"/>
        <source>Units</source>
        <translation>Einheiten</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="137"/>
        <source>Units of stresses and displacements in the legend, the cursor read-out and query lines</source>
        <translation>Einheiten der Spannungen und Verschiebungen in Legende, Cursoranzeige und Abfragelinien</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="148"/>
        <source>Stresses</source>
        <translation>Spannungen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="149"/>
        <source>kPa, or MPa from 1 MPa on</source>
        <translation>kPa, ab 1 MPa in MPa</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="150"/>
        <source>kPa</source>
        <translation>kPa</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="151"/>
        <source>MPa</source>
        <translation>MPa</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="153"/>
        <source>Displacements</source>
        <translation>Verschiebungen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="154"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="155"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="170"/>
        <source>Rainbow</source>
        <translation>Regenbogen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="171"/>
        <source>Viridis</source>
        <translation>Viridis</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="172"/>
        <source>Grey</source>
        <translation>Grau</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="173"/>
        <source>Blue–white–red</source>
        <translation>Blau–Weiß–Rot</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="174"/>
        <source>Colour map of the scale</source>
        <translation>Farbskala</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="180"/>
        <source>smooth</source>
        <translation>stufenlos</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="181"/>
        <source> bands</source>
        <translation> Stufen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="182"/>
        <source>Number of colour bands (contours); smooth = a continuous scale</source>
        <translation>Anzahl der Farbstufen (Isoflächen); stufenlos = kontinuierliche Skala</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="185"/>
        <source>Range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="196"/>
        <source>Lower end of the colour scale in the legend&apos;s units; empty = automatic</source>
        <translation>Unteres Ende der Farbskala in den Einheiten der Legende; leer = automatisch</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="197"/>
        <source>Upper end of the colour scale in the legend&apos;s units; empty = automatic</source>
        <translation>Oberes Ende der Farbskala in den Einheiten der Legende; leer = automatisch</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="226"/>
        <source>Pore pressure u</source>
        <translation>Porenwasserdruck u</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ResultToolBar.cpp" line="308"/>
        <source>×%1 (auto)</source>
        <translation>×%1 (auto)</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/widgets/ResultToolBar.cpp" line="311"/>
        <source>⚠ %n element(s) drawn inside out: lower the scale</source>
        <translation>
            <numerusform>⚠ %n Element umgestülpt gezeichnet: Überhöhung verringern</numerusform>
            <numerusform>⚠ %n Elemente umgestülpt gezeichnet: Überhöhung verringern</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mcdda::gui::RunMenu</name>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="9"/>
        <location filename="../gui/widgets/RunMenu.cpp" line="23"/>
        <source>&amp;Run</source>
        <translation>Be&amp;rechnung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="19"/>
        <source>&amp;Mesh</source>
        <translation>&amp;Netz</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="20"/>
        <source>Cut the blocks and mesh them in the background (edits do this by themselves); the statistics go to the status bar and the Messages dock</source>
        <translation>Blöcke schneiden und im Hintergrund vernetzen (Änderungen tun das von selbst); die Kennzahlen erscheinen in der Statusleiste und unter Meldungen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="24"/>
        <source>Analyse the model; the picture follows the run</source>
        <translation>Das Modell berechnen; das Bild folgt der Berechnung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="26"/>
        <location filename="../gui/widgets/RunMenu.cpp" line="49"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="27"/>
        <source>Pause or resume the run</source>
        <translation>Die Berechnung unterbrechen oder fortsetzen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="28"/>
        <source>&amp;Stop</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="29"/>
        <source>Stop the run after the current step; the results so far are kept</source>
        <translation>Die Berechnung nach dem aktuellen Schritt abbrechen; die bisherigen Ergebnisse bleiben erhalten</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="32"/>
        <source>Results &amp;Folder...</source>
        <translation>Ergebnis&amp;ordner...</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="33"/>
        <source>Choose where runs write their files</source>
        <translation>Wählen, wohin Berechnungen ihre Dateien schreiben</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="38"/>
        <source>Run</source>
        <translation>Berechnung</translation>
    </message>
    <message>
        <location filename="../gui/widgets/RunMenu.cpp" line="49"/>
        <source>Res&amp;ume</source>
        <translation>&amp;Fortsetzen</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::RunMessages</name>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="27"/>
        <source>Model: %1</source>
        <translation>Modell: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="31"/>
        <source>Times: read %1 ms, checked %2 ms, cut %3 ms, meshed %4 ms</source>
        <translation>Zeiten: gelesen %1 ms, geprüft %2 ms, zerlegt %3 ms, vernetzt %4 ms</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="48"/>
        <source>%1 blocks, %2 nodes, %3 triangles</source>
        <translation>%1 Blöcke, %2 Knoten, %3 Dreiecke</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="53"/>
        <source>angles: smallest %1°, largest %2°</source>
        <translation>Winkel: kleinster %1°, größter %2°</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="56"/>
        <source>areas: smallest %1 m², largest %2 m², total %3 m²</source>
        <translation>Flächen: kleinste %1 m², größte %2 m², gesamt %3 m²</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="59"/>
        <source>sharpest block corner: %1°</source>
        <translation>spitzeste Blockecke: %1°</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="61"/>
        <source>triangles by smallest angle: %1</source>
        <translation>Dreiecke nach kleinstem Winkel: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="73"/>
        <source>Permanent displacement (relative to the base): largest %1 mm at (%2, %3)</source>
        <translation>Bleibende Verschiebung (relativ zur Basis): größte %1 mm bei (%2, %3)</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="79"/>
        <source>; %1: ux %2 mm, uy %3 mm</source>
        <translation>; %1: ux %2 mm, uy %3 mm</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="94"/>
        <source>Draw a region to start</source>
        <translation>Zuerst einen Bereich zeichnen</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="96"/>
        <source>Not meshed: %n error(s)</source>
        <translation>
            <numerusform>Nicht vernetzt: %n Fehler</numerusform>
            <numerusform>Nicht vernetzt: %n Fehler</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="99"/>
        <source>%1 blocks, %2 nodes, %3 elements, smallest angle %4°</source>
        <translation>%1 Blöcke, %2 Knoten, %3 Elemente, kleinster Winkel %4°</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="112"/>
        <source>pre-processing stopped without a message</source>
        <translation>die Vorverarbeitung brach ohne Meldung ab</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="121"/>
        <source>... and %n more</source>
        <translation>
            <numerusform>... und %n weitere</numerusform>
            <numerusform>... und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="128"/>
        <source>load step %1/%2  contacts open/sliding/locked %3/%4/%5  plastic iterations %6  yielding %7</source>
        <translation>Lastschritt %1/%2  Kontakte offen/gleitend/haftend %3/%4/%5  plastische Iterationen %6  plastifizierend %7</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="137"/>
        <source>step %1/%2  t = %3 s  dt = %4 s  contacts open/sliding/locked %5/%6/%7  plastic iterations %8  yielding %9</source>
        <translation>Zeitschritt %1/%2  t = %3 s  dt = %4 s  Kontakte offen/gleitend/haftend %5/%6/%7  plastische Iterationen %8  plastifizierend %9</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="152"/>
        <source>Step %1: equilibrium iteration %2, out-of-balance %3 (tolerance %4), %n point(s) yielding</source>
        <translation>
            <numerusform>Schritt %1: Gleichgewichtsiteration %2, Ungleichgewicht %3 (Toleranz %4), %n Punkt plastifiziert</numerusform>
            <numerusform>Schritt %1: Gleichgewichtsiteration %2, Ungleichgewicht %3 (Toleranz %4), %n Punkte plastifiziert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="163"/>
        <source>Strength reduction: trial %1, strengths divided by %2...</source>
        <translation>Festigkeitsreduktion: Versuch %1, Festigkeiten geteilt durch %2 …</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="170"/>
        <source>largest displacement %1 m, %n iteration(s), %2 s</source>
        <translation>
            <numerusform>größte Verschiebung %1 m, %n Iteration, %2 s</numerusform>
            <numerusform>größte Verschiebung %1 m, %n Iterationen, %2 s</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="176"/>
        <source>Trial %1: F = %2 stands (%3)</source>
        <translation>Versuch %1: F = %2 steht (%3)</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="180"/>
        <source>Trial %1: F = %2 does not stand (%3): %4</source>
        <translation>Versuch %1: F = %2 steht nicht (%3): %4</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="190"/>
        <source>above %1</source>
        <translation>über %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="192"/>
        <source>below %1</source>
        <translation>unter %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="194"/>
        <source>between %1 and %2</source>
        <translation>zwischen %1 und %2</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="197"/>
        <source>not found</source>
        <translation>nicht gefunden</translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="203"/>
        <source>Factor of safety %1 (%n trial(s)).</source>
        <translation>
            <numerusform>Sicherheitsfaktor %1 (%n Versuch).</numerusform>
            <numerusform>Sicherheitsfaktor %1 (%n Versuche).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="205"/>
        <source>Factor of safety %1: the model stands with its strengths divided by %2, not by %3 (%n trial(s)).</source>
        <translation>
            <numerusform>Sicherheitsfaktor %1: das Modell steht mit durch %2 geteilten Festigkeiten, nicht mit durch %3 geteilten (%n Versuch).</numerusform>
            <numerusform>Sicherheitsfaktor %1: das Modell steht mit durch %2 geteilten Festigkeiten, nicht mit durch %3 geteilten (%n Versuche).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../gui/session/RunMessages.cpp" line="216"/>
        <source>Run completed: %n step(s).</source>
        <translation>
            <numerusform>Berechnung abgeschlossen: %n Schritt.</numerusform>
            <numerusform>Berechnung abgeschlossen: %n Schritte.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="221"/>
        <source>Run ended but the model is not in equilibrium: %1</source>
        <translation>Berechnung beendet, aber das Modell ist nicht im Gleichgewicht: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="223"/>
        <source>Run stopped after step %1.</source>
        <translation>Berechnung nach Schritt %1 abgebrochen.</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="224"/>
        <source>The model collapsed: %1</source>
        <translation>Das Modell ist kollabiert: %1</translation>
    </message>
    <message>
        <location filename="../gui/session/RunMessages.cpp" line="225"/>
        <source>The run failed: %1</source>
        <translation>Die Berechnung ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetAnalysisSettingsCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="94"/>
        <source>Change analysis settings</source>
        <translation>Berechnungseinstellungen ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetInitialStressCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="147"/>
        <source>Change in-situ stress</source>
        <translation>Primärspannungszustand ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetJointMaterialCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="139"/>
        <source>Change joint material &quot;%1&quot;</source>
        <translation>Kluftmaterial „%1“ ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::SetMaterialCommand</name>
    <message>
        <location filename="../gui/document/EditCommands.cpp" line="78"/>
        <source>Change material &quot;%1&quot;</source>
        <translation>Material „%1“ ändern</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::StagesPanel</name>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="81"/>
        <source>fixed point</source>
        <translation>Festpunkt</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="82"/>
        <source>roller</source>
        <translation>Rollenlager</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="83"/>
        <source>point load</source>
        <translation>Einzellast</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="84"/>
        <source>edge pressure</source>
        <translation>Randdruck</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="85"/>
        <source>bolt</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="93"/>
        <source>line with %1 points</source>
        <translation>Linie mit %1 Punkten</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="94"/>
        <source>dry</source>
        <translation>trocken</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="117"/>
        <source>Choose a stage to see the model as it stands in it; the first row shows every region</source>
        <translation>Eine Bauphase wählen, um das Modell so zu sehen, wie es in ihr steht; die erste Zeile zeigt alle Bereiche</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="119"/>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="121"/>
        <source>Add a stage at the end (10 steps, the model&apos;s analysis settings)</source>
        <translation>Eine Bauphase am Ende hinzufügen (10 Schritte, die Berechnungseinstellungen des Modells)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="122"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="124"/>
        <source>Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="126"/>
        <source>Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="130"/>
        <source>Name of the stage (results, tree, messages)</source>
        <translation>Name der Bauphase (Ergebnisse, Baum, Meldungen)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="132"/>
        <source>Regions removed at the start of the stage (an excavation)</source>
        <translation>Bereiche, die zu Beginn der Bauphase entfernt werden (ein Ausbruch)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="134"/>
        <source>Regions added at the start of the stage (backfill, a liner); absent before</source>
        <translation>Bereiche, die zu Beginn der Bauphase hinzukommen (Verfüllung, Ausbau); vorher nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="136"/>
        <source>Supports, loads and bolts added at the start of the stage; absent before</source>
        <translation>Lager, Lasten und Anker, die zu Beginn der Bauphase hinzukommen; vorher nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="138"/>
        <source>Supports, loads and bolts taken away at the start of the stage</source>
        <translation>Lager, Lasten und Anker, die zu Beginn der Bauphase entfernt werden</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="141"/>
        <source>over all steps</source>
        <translation>über alle Schritte</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="142"/>
        <source> steps</source>
        <translation> Schritte</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="143"/>
        <source>Over how many steps the forces the stage leaves out of balance (an excavation&apos;s) are released, linearly; fewer steps release them faster</source>
        <translation>Über wie viele Schritte die Ungleichgewichtskräfte der Bauphase (etwa eines Ausbruchs) linear freigesetzt werden; weniger Schritte setzen sie schneller frei</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="148"/>
        <source>The ground water in the stage: the piezometric line drawn blue in the picture</source>
        <translation>Das Grundwasser in der Bauphase: die im Bild blau gezeichnete Piezometerlinie</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="149"/>
        <source>Draw...</source>
        <translation>Zeichnen...</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="151"/>
        <source>Draw the water table of this stage with the Water Table tool: click its points from left to right, double-click or Enter finishes</source>
        <translation>Den Grundwasserspiegel dieser Bauphase mit dem Werkzeug Grundwasserspiegel zeichnen: seine Punkte von links nach rechts anklicken, Doppelklick oder Eingabetaste beendet</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="153"/>
        <source>Dry</source>
        <translation>Trocken</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="155"/>
        <source>No ground water from this stage on (dewatered)</source>
        <translation>Kein Grundwasser ab dieser Bauphase (entwässert)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="156"/>
        <source>As Before</source>
        <translation>Wie davor</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="158"/>
        <source>The stage keeps the water of the stage before (the model&apos;s for the first stage)</source>
        <translation>Die Bauphase behält das Grundwasser der Bauphase davor (bei der ersten das des Modells)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="164"/>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="179"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="140"/>
        <source>Number of load steps of the stage (time steps in a dynamic stage)</source>
        <translation>Anzahl der Lastschritte der Bauphase (Zeitschritte in einer dynamischen)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="159"/>
        <source>Reset displacements at its start</source>
        <translation>Verschiebungen zu Beginn zurücksetzen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="161"/>
        <source>Displacements are reported from the start of this stage, as RS2 and PLAXIS reset them: the settlement under gravity in the stage before no longer shows. Stresses and the shape stay. Ticked by itself for the stage after the first when the model has gravity</source>
        <translation>Verschiebungen werden ab Beginn dieser Bauphase angegeben, wie RS2 und PLAXIS sie zurücksetzen: die Setzung unter Eigengewicht in der Phase davor ist nicht mehr zu sehen. Spannungen und Form bleiben. Für die Phase nach der ersten von selbst angekreuzt, wenn das Modell Schwerkraft hat</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="180"/>
        <source>Excavate regions</source>
        <translation>Aushub von Bereichen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="181"/>
        <source>Build regions (fill, liner)</source>
        <translation>Einbau von Bereichen (Verfüllung, Schale)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="182"/>
        <source>Install supports, loads, bolts</source>
        <translation>Stützmittel, Lasten, Anker einbauen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="183"/>
        <source>Remove supports, loads, bolts</source>
        <translation>Stützmittel, Lasten, Anker ausbauen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="185"/>
        <source>Release</source>
        <translation>Freisetzung</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="189"/>
        <source>Ground water</source>
        <translation>Grundwasser</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="195"/>
        <source>Own (else as the stage before)</source>
        <translation>Eigener (sonst wie die Bauphase davor)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="197"/>
        <source>The stage sets its own seismic coefficient (e.g. a pseudo-static earthquake stage); cleared, it keeps the stage before&apos;s (the model&apos;s for the first stage)</source>
        <translation>Die Bauphase setzt ihren eigenen Erdbebenbeiwert (z. B. eine pseudostatische Erdbebenphase); ohne Haken gilt der Beiwert der Bauphase davor (für die erste Bauphase der des Modells)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="201"/>
        <source>Horizontal seismic coefficient: every block carries kh·g per unit mass, towards +x for kh &gt; 0</source>
        <translation>Horizontaler Erdbebenbeiwert: jeder Block erhält kh·g je Masseneinheit, für kh &gt; 0 in +x-Richtung</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="204"/>
        <source>Vertical seismic coefficient: kv·g per unit mass, upwards for kv &gt; 0</source>
        <translation>Vertikaler Erdbebenbeiwert: kv·g je Masseneinheit, für kv &gt; 0 nach oben</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="205"/>
        <source>Seismic coefficient</source>
        <translation>Erdbebenbeiwert</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="207"/>
        <source>kh</source>
        <translation>kh</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="209"/>
        <source>kv</source>
        <translation>kv</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="213"/>
        <source>Analysis</source>
        <translation>Berechnung</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="281"/>
        <source>Model as drawn (every region)</source>
        <translation>Modell wie gezeichnet (alle Bereiche)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="283"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="286"/>
        <source>No stages: the model is analysed in one go. Add one to excavate or build regions step by step.</source>
        <translation>Keine Bauphasen: das Modell wird in einem Zug berechnet. Eine hinzufügen, um Bereiche schrittweise auszubrechen oder einzubauen.</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="309"/>
        <source>region %1</source>
        <translation>Bereich %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="323"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="375"/>
        <source>as the stage before (%1)</source>
        <translation>wie in der Bauphase davor (%1)</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="435"/>
        <source>Edit stage &quot;%1&quot;</source>
        <translation>Bauphase „%1“ ändern</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="442"/>
        <source>stage %1</source>
        <translation>Bauphase %1</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="450"/>
        <source>Add stage &quot;%1&quot;</source>
        <translation>Bauphase „%1“ hinzufügen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="461"/>
        <source>Remove stage &quot;%1&quot;</source>
        <translation>Bauphase „%1“ entfernen</translation>
    </message>
    <message>
        <location filename="../gui/panels/StagesPanel.cpp" line="470"/>
        <source>Move stage &quot;%1&quot;</source>
        <translation>Bauphase „%1“ verschieben</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::StepSlider</name>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="16"/>
        <source>Saved step shown</source>
        <translation>Angezeigter gespeicherter Schritt</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="24"/>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="70"/>
        <source>no saved steps</source>
        <translation>keine gespeicherten Schritte</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="79"/>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="80"/>
        <source>load step %1 (%2)</source>
        <translation>Lastschritt %1 (%2)</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="83"/>
        <source>%1 of %2, t = %3 s</source>
        <translation>%1 von %2, t = %3 s</translation>
    </message>
    <message>
        <location filename="../gui/results/StepSlider.cpp" line="84"/>
        <source>step %1 (%2)</source>
        <translation>Schritt %1 (%2)</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::UnbalancedPlot</name>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="31"/>
        <source>unbalanced-force ratio</source>
        <translation>Ungleichgewichtsverhältnis</translation>
    </message>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="34"/>
        <source>equilibrium limit</source>
        <translation>Gleichgewichtsgrenze</translation>
    </message>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="42"/>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="45"/>
        <source>ratio</source>
        <translation>Verhältnis</translation>
    </message>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="57"/>
        <source>Largest out-of-balance nodal force over the largest applied force, per step; a run ending above the dashed limit is not in equilibrium</source>
        <translation>Größte Ungleichgewichtskraft an einem Knoten durch die größte aufgebrachte Kraft, je Schritt; eine Berechnung, die über der gestrichelten Grenze endet, ist nicht im Gleichgewicht</translation>
    </message>
    <message>
        <location filename="../gui/results/UnbalancedPlot.cpp" line="89"/>
        <source>The unbalanced-force ratio of each step is plotted here during a run.</source>
        <translation>Das Ungleichgewichtsverhältnis jedes Schritts wird hier während einer Berechnung dargestellt.</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::ViewMenu</name>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="11"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="13"/>
        <source>&amp;Fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="16"/>
        <source>Show the whole model</source>
        <translation>Das ganze Modell zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="26"/>
        <source>&amp;Mesh</source>
        <translation>&amp;Netz</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="26"/>
        <source>Show the element edges</source>
        <translation>Die Elementkanten zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="27"/>
        <source>&amp;Joints</source>
        <translation>&amp;Klüfte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="27"/>
        <source>Show the joint traces</source>
        <translation>Die Kluftspuren zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="28"/>
        <source>&amp;Supports</source>
        <translation>A&amp;uflager</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="28"/>
        <source>Show fixed points and rollers</source>
        <translation>Festpunkte und Rollenlager zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="29"/>
        <source>&amp;Loads</source>
        <translation>&amp;Lasten</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="29"/>
        <source>Show point loads and edge pressures</source>
        <translation>Punktlasten und Kantendrücke zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="30"/>
        <source>Measurement &amp;points</source>
        <translation>&amp;Messpunkte</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="30"/>
        <source>Show the measurement points</source>
        <translation>Die Messpunkte zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="31"/>
        <source>Le&amp;gend</source>
        <translation>Le&amp;gende</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="31"/>
        <source>Show the legend</source>
        <translation>Die Legende zeigen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="33"/>
        <source>Snap to &amp;Grid</source>
        <translation>Am &amp;Raster fangen</translation>
    </message>
    <message>
        <location filename="../gui/widgets/ViewMenu.cpp" line="37"/>
        <source>Drawn points snap to a grid (0.5 m) and to nearby region vertices</source>
        <translation>Gezeichnete Punkte rasten auf einem Raster (0,5 m) und an nahen Bereichsecken ein</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::WindowStatusBar</name>
    <message>
        <location filename="../gui/widgets/WindowStatusBar.cpp" line="42"/>
        <source>x = %1 m   y = %2 m</source>
        <translation>x = %1 m   y = %2 m</translation>
    </message>
    <message>
        <location filename="../gui/widgets/WindowStatusBar.cpp" line="68"/>
        <source>Factor of safety %1</source>
        <translation>Sicherheitsfaktor %1</translation>
    </message>
</context>
<context>
    <name>mcdda::gui::form</name>
    <message>
        <location filename="../gui/panels/FormFields.cpp" line="57"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location filename="../gui/panels/FormFields.cpp" line="243"/>
        <source>Static</source>
        <translation>Statisch</translation>
    </message>
    <message>
        <location filename="../gui/panels/FormFields.cpp" line="244"/>
        <source>Dynamic</source>
        <translation>Dynamisch</translation>
    </message>
    <message>
        <location filename="../gui/panels/FormFields.cpp" line="245"/>
        <source>Strength reduction</source>
        <translation>Festigkeitsreduktion</translation>
    </message>
    <message>
        <location filename="../gui/panels/FormFields.cpp" line="246"/>
        <source>Static: each step ends at rest (velocities reset), for equilibrium and collapse loads. Dynamic: velocities carry over, for falls and sliding. Strength reduction: the factor of safety, the largest factor c and tan φ can be divided by while the model still stands (of the whole model, or as the last stage: a safety stage starting from the stresses of the stages before)</source>
        <translation>Statisch: jeder Schritt endet in Ruhe (Geschwindigkeiten zurückgesetzt), für Gleichgewicht und Traglasten. Dynamisch: Geschwindigkeiten bleiben erhalten, für Fallen und Gleiten. Festigkeitsreduktion: der Sicherheitsfaktor, der größte Faktor, durch den c und tan φ geteilt werden können, während das Modell noch steht (des ganzen Modells oder als letzte Bauphase: eine Sicherheitsphase, die von den Spannungen der Bauphasen davor ausgeht)</translation>
    </message>
    <message>
        <location filename="../gui/panels/AdvancedSettings.cpp" line="54"/>
        <source>Advanced</source>
        <translation>Erweitert</translation>
    </message>
    <message>
        <location filename="../gui/panels/AdvancedSettings.cpp" line="60"/>
        <source>The numerical settings of the DDA solver (time step, contact penalty, dynamic ratio, largest displacement per step, tolerances); their defaults suit most models</source>
        <translation>Die numerischen Einstellungen des DDA-Lösers (Zeitschritt, Kontaktsteifigkeit, dynamischer Faktor, größte Verschiebung je Schritt, Toleranzen); ihre Vorgaben passen für die meisten Modelle</translation>
    </message>
    <message>
        <location filename="../gui/panels/AdvancedSettings.cpp" line="92"/>
        <source>Default %1. %2.</source>
        <translation>Vorgabe %1. %2.</translation>
    </message>
    <message>
        <location filename="../gui/panels/AdvancedSettings.cpp" line="104"/>
        <source>Time steps</source>
        <translation>Zeitschritte</translation>
    </message>
    <message>
        <location filename="../gui/panels/AdvancedSettings.cpp" line="104"/>
        <source>Load steps</source>
        <translation>Lastschritte</translation>
    </message>
</context>
<context>
    <name>mcdda::view</name>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="54"/>
        <location filename="../gui/view/ResultProbe.cpp" line="70"/>
        <location filename="../gui/view/ResultScene.cpp" line="57"/>
        <source>elastic</source>
        <translation>elastisch</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="55"/>
        <location filename="../gui/view/ResultProbe.cpp" line="71"/>
        <location filename="../gui/view/ResultScene.cpp" line="57"/>
        <source>yielded before</source>
        <translation>früher plastifiziert</translation>
    </message>
    <message>
        <location filename="../gui/results/QueryPlot.cpp" line="56"/>
        <location filename="../gui/view/ResultProbe.cpp" line="72"/>
        <location filename="../gui/view/ResultScene.cpp" line="57"/>
        <source>yielding now</source>
        <translation>plastifiziert jetzt</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="82"/>
        <source>plastic state</source>
        <translation>plastischer Zustand</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="83"/>
        <source>plastic strain</source>
        <translation>plastische Dehnung</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="104"/>
        <source>displacement increment</source>
        <translation>Verschiebungsinkrement</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="106"/>
        <source>plastic strain increment</source>
        <translation>plastisches Dehnungsinkrement</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="84"/>
        <source>displacement</source>
        <translation>Verschiebung</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="85"/>
        <source>x displacement</source>
        <translation>Verschiebung x</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="86"/>
        <source>y displacement</source>
        <translation>Verschiebung y</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="87"/>
        <source>stress xx</source>
        <translation>Spannung xx</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="88"/>
        <source>stress yy</source>
        <translation>Spannung yy</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="89"/>
        <source>shear stress xy</source>
        <translation>Schubspannung xy</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="90"/>
        <source>principal stress 1</source>
        <translation>Hauptspannung 1</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="91"/>
        <source>principal stress 3</source>
        <translation>Hauptspannung 3</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="1041"/>
        <source>compression +</source>
        <translation>Druck +</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="1042"/>
        <source>tension +</source>
        <translation>Zug +</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="900"/>
        <source>block boundary</source>
        <translation>Blockrand</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="94"/>
        <source>pore pressure</source>
        <translation>Porenwasserdruck</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="95"/>
        <source>effective stress xx</source>
        <translation>effektive Spannung xx</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="96"/>
        <source>effective stress yy</source>
        <translation>effektive Spannung yy</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="98"/>
        <source>effective principal stress 1</source>
        <translation>effektive Hauptspannung 1</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="100"/>
        <source>effective principal stress 3</source>
        <translation>effektive Hauptspannung 3</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="902"/>
        <source>joint</source>
        <translation>Kluft</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="905"/>
        <source>water table</source>
        <translation>Grundwasserspiegel</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="912"/>
        <source>contact force, largest</source>
        <translation>Kontaktkraft, größte</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="915"/>
        <source>bolt</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="919"/>
        <source>joint slip, largest</source>
        <translation>Kluftverschiebung, größte</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="924"/>
        <source>joint opening, largest</source>
        <translation>Kluftöffnung, größte</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="948"/>
        <source>uniform:</source>
        <translation>gleichförmig:</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="994"/>
        <source>strengths divided by</source>
        <translation>Festigkeiten geteilt durch</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="999"/>
        <source>load step</source>
        <translation>Lastschritt</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="1000"/>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="1005"/>
        <source>stage</source>
        <translation>Bauphase</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultScene.cpp" line="1012"/>
        <source>deformed</source>
        <translation>verformt</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="158"/>
        <source>Unassigned material</source>
        <translation>Kein Material</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="160"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="167"/>
        <source>Legend</source>
        <translation>Legende</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="197"/>
        <source>Region boundary</source>
        <translation>Bereichsrand</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="198"/>
        <source>Block boundary</source>
        <translation>Blockrand</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="200"/>
        <source>Joint</source>
        <translation>Kluft</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="202"/>
        <source>Water table</source>
        <translation>Grundwasserspiegel</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="204"/>
        <source>Fixed point</source>
        <translation>Festpunkt</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="211"/>
        <source>Fixed line (x and y)</source>
        <translation>Feste Linie (x und y)</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="213"/>
        <source>Roller</source>
        <translation>Rollenlager</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="215"/>
        <source>Bolt</source>
        <translation>Anker</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="217"/>
        <source>Absorbing boundary</source>
        <translation>Absorbierender Rand</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="219"/>
        <source>Compliant base (earthquake input)</source>
        <translation>Nachgiebige Basis (Erdbebeneingang)</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="221"/>
        <source>Point load</source>
        <translation>Punktlast</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="223"/>
        <source>Edge pressure</source>
        <translation>Kantendruck</translation>
    </message>
    <message>
        <location filename="../gui/view/SceneLegend.cpp" line="225"/>
        <source>Measurement point</source>
        <translation>Messpunkt</translation>
    </message>
    <message>
        <location filename="../gui/view/ResultProbe.cpp" line="58"/>
        <source>bolt, axial force</source>
        <translation>Anker, Axialkraft</translation>
    </message>
</context>
</TS>
