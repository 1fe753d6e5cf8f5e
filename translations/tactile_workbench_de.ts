<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ContactClass</name>
    <message>
        <source>No contact</source>
        <translation>Kein Kontakt</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>Ecke</translation>
    </message>
    <message>
        <source>Leaving wall</source>
        <translation>Wand verlassen</translation>
    </message>
    <message>
        <source>Dead path</source>
        <translation>Sackgasse</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keins)</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>Gehe zu</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>Lernen</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <source>Open a database</source>
        <translation>Eine Datenbank öffnen</translation>
    </message>
    <message>
        <source>Import run files</source>
        <translation>Laufdateien importieren</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>Undo the last label edit</source>
        <translation>Die letzte Label-Änderung rückgängig machen</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Label as %1</source>
        <translation>Als %1 labeln</translation>
    </message>
    <message>
        <source>Delete the segments under the cursor</source>
        <translation>Die Segmente unter dem Cursor löschen</translation>
    </message>
    <message>
        <source>Move the segment&apos;s start one step left</source>
        <translation>Den Segmentanfang einen Schritt nach links verschieben</translation>
    </message>
    <message>
        <source>Move the segment&apos;s start one step right</source>
        <translation>Den Segmentanfang einen Schritt nach rechts verschieben</translation>
    </message>
    <message>
        <source>Move the segment&apos;s end one step left</source>
        <translation>Das Segmentende einen Schritt nach links verschieben</translation>
    </message>
    <message>
        <source>Move the segment&apos;s end one step right</source>
        <translation>Das Segmentende einen Schritt nach rechts verschieben</translation>
    </message>
    <message>
        <source>Clear the selection (in a text field: leave the field)</source>
        <translation>Die Auswahl aufheben (in einem Textfeld: das Feld verlassen)</translation>
    </message>
    <message>
        <source>Next step</source>
        <translation>Nächster Schritt</translation>
    </message>
    <message>
        <source>Previous step</source>
        <translation>Vorheriger Schritt</translation>
    </message>
    <message>
        <source>Forward 10 steps</source>
        <translation>10 Schritte vor</translation>
    </message>
    <message>
        <source>Back 10 steps</source>
        <translation>10 Schritte zurück</translation>
    </message>
    <message>
        <source>Forward 100 steps</source>
        <translation>100 Schritte vor</translation>
    </message>
    <message>
        <source>Back 100 steps</source>
        <translation>100 Schritte zurück</translation>
    </message>
    <message>
        <source>Forward one screen</source>
        <translation>Eine Bildschirmbreite vor</translation>
    </message>
    <message>
        <source>Back one screen</source>
        <translation>Eine Bildschirmbreite zurück</translation>
    </message>
    <message>
        <source>First step</source>
        <translation>Erster Schritt</translation>
    </message>
    <message>
        <source>Last step</source>
        <translation>Letzter Schritt</translation>
    </message>
    <message>
        <source>Play or pause</source>
        <translation>Abspielen oder anhalten</translation>
    </message>
    <message>
        <source>Route: robot close-up or whole scene</source>
        <translation>Route: Roboter-Nahansicht oder ganze Szene</translation>
    </message>
    <message>
        <source>Zoom the timelines out to the whole run</source>
        <translation>Die Zeitleisten auf den ganzen Lauf herauszoomen</translation>
    </message>
    <message>
        <source>Train and sweep</source>
        <translation>Trainieren und Sweep</translation>
    </message>
    <message>
        <source>Show a model&apos;s predictions</source>
        <translation>Die Vorhersagen eines Modells anzeigen</translation>
    </message>
    <message>
        <source>Next stretch where the model disagrees with the labels</source>
        <translation>Nächster Abschnitt, in dem das Modell von den Labels abweicht</translation>
    </message>
    <message>
        <source>Previous stretch where the model disagrees with the labels</source>
        <translation>Vorheriger Abschnitt, in dem das Modell von den Labels abweicht</translation>
    </message>
    <message>
        <source>This list of keyboard shortcuts</source>
        <translation>Diese Liste der Tastenkürzel</translation>
    </message>
    <message>
        <source>New simulation window</source>
        <translation>Neues Simulatorfenster</translation>
    </message>
    <message>
        <source>Label the selection (or the visible steps) from the predictions&apos; model</source>
        <translation>Auswahl (oder sichtbare Schritte) mit dem Modell der Vorhersagen beschriften</translation>
    </message>
    <message>
        <source>Next stretch where the model is unsure (below the threshold in Preferences)</source>
        <translation>Nächster Abschnitt, in dem das Modell unsicher ist (unter der Schwelle in den Einstellungen)</translation>
    </message>
</context>
<context>
    <name>SimKeys</name>
    <message>
        <source>Faster forward by a large step (+20 units/s)</source>
        <translation>Vorwärts schneller, großer Schritt (+20 Einheiten/s)</translation>
    </message>
    <message>
        <source>Slower (or backward) by a large step (-20 units/s)</source>
        <translation>Langsamer (oder rückwärts), großer Schritt (-20 Einheiten/s)</translation>
    </message>
    <message>
        <source>Faster forward by a small step (+5 units/s)</source>
        <translation>Vorwärts schneller, kleiner Schritt (+5 Einheiten/s)</translation>
    </message>
    <message>
        <source>Slower (or backward) by a small step (-5 units/s)</source>
        <translation>Langsamer (oder rückwärts), kleiner Schritt (-5 Einheiten/s)</translation>
    </message>
    <message>
        <source>Turn left by a large step (+0.2 rad/s)</source>
        <translation>Nach links drehen, großer Schritt (+0.2 rad/s)</translation>
    </message>
    <message>
        <source>Turn right by a large step (-0.2 rad/s)</source>
        <translation>Nach rechts drehen, großer Schritt (-0.2 rad/s)</translation>
    </message>
    <message>
        <source>Turn left by a small step (+0.05 rad/s)</source>
        <translation>Nach links drehen, kleiner Schritt (+0.05 rad/s)</translation>
    </message>
    <message>
        <source>Turn right by a small step (-0.05 rad/s)</source>
        <translation>Nach rechts drehen, kleiner Schritt (-0.05 rad/s)</translation>
    </message>
    <message>
        <source>Stop (v = 0, omega = 0)</source>
        <translation>Anhalten (v = 0, omega = 0)</translation>
    </message>
    <message>
        <source>Robot close-up / whole scene (close-up only in experiment mode)</source>
        <translation>Roboter-Nahansicht / ganze Szene (im Experimentmodus nur Nahansicht)</translation>
    </message>
    <message>
        <source>Pause / go on</source>
        <translation>Pause / weiter</translation>
    </message>
    <message>
        <source>One step (while paused)</source>
        <translation>Ein Schritt (während der Pause)</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan on the picture / off (autonomous mode)</source>
        <translation>Tastkarte und Plan des Navigators im Bild ein / aus (autonomer Modus)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tactile Workbench: tactile-navigation research desktop</source>
        <translation>Tactile Workbench: Arbeitsplatz für die Forschung zur taktilen Navigation</translation>
    </message>
    <message>
        <source>Open the run database DB (default: the last one used).</source>
        <translation>Die Laufdatenbank DB öffnen (Vorgabe: die zuletzt benutzte).</translation>
    </message>
    <message>
        <source>Open the run named NAME.</source>
        <translation>Den Lauf namens NAME öffnen.</translation>
    </message>
    <message>
        <source>Put the cursor on step K.</source>
        <translation>Den Cursor auf Schritt K setzen.</translation>
    </message>
    <message>
        <source>--step needs a step number, got &apos;%1&apos;</source>
        <translation>--step braucht eine Schrittnummer, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--run needs --db</source>
        <translation>--run braucht --db</translation>
    </message>
    <message>
        <source>%1: no such database</source>
        <translation>%1: Datenbank nicht gefunden</translation>
    </message>
    <message>
        <source>Render the window (or with --sweep the results window) at 1600x1000 to the PNG file FILE, then quit.</source>
        <translation>Das Fenster (mit --sweep das Ergebnisfenster) in 1600x1000 als PNG-Datei FILE speichern, dann beenden.</translation>
    </message>
    <message>
        <source>Open the results of the stored sweep ID (needs --db).</source>
        <translation>Die Ergebnisse des gespeicherten Sweeps ID öffnen (braucht --db).</translation>
    </message>
    <message>
        <source>--sweep needs --db</source>
        <translation>--sweep braucht --db</translation>
    </message>
    <message>
        <source>--model needs --run</source>
        <translation>--model braucht --run</translation>
    </message>
    <message>
        <source>--sweep needs a sweep id, got &apos;%1&apos;</source>
        <translation>--sweep braucht eine Sweep-ID, erhalten: „%1“</translation>
    </message>
    <message>
        <source>Open the simulator window on SCENE (a built-in scene, a scene JSON file or random:N:SEED); runs go into --db (or the last database).</source>
        <translation>Das Simulatorfenster mit der Szene SCENE öffnen (eine eingebaute Szene, eine Szenen-JSON-Datei oder random:N:SEED); Läufe gehen in --db (oder die zuletzt benutzte Datenbank).</translation>
    </message>
    <message>
        <source>With --simulate: practice (default), experiment or autonomous.</source>
        <translation>Mit --simulate: practice (Übung, Vorgabe), experiment (Experiment) oder autonomous (autonom).</translation>
    </message>
    <message>
        <source>With --simulate: the subject&apos;s name.</source>
        <translation>Mit --simulate: der Name des Probanden.</translation>
    </message>
    <message>
        <source>With --simulate: start a run and replay the v, omega commands of the run file FILE, one a step.</source>
        <translation>Mit --simulate: einen Lauf starten und die Befehle v, omega der Laufdatei FILE abspielen, einen je Schritt.</translation>
    </message>
    <message>
        <source>With --simulate: steps per second (default 10; 0 as fast as possible).</source>
        <translation>Mit --simulate: Schritte pro Sekunde (Vorgabe 10; 0 so schnell wie möglich).</translation>
    </message>
    <message>
        <source>With --simulate: show the data panel.</source>
        <translation>Mit --simulate: den Datenbereich anzeigen.</translation>
    </message>
    <message>
        <source>With --simulate: show the whole scene where allowed.</source>
        <translation>Mit --simulate: die ganze Szene zeigen, wo erlaubt.</translation>
    </message>
    <message>
        <source>no stored model named &apos;%1&apos;</source>
        <translation>kein gespeichertes Modell namens „%1“</translation>
    </message>
    <message>
        <source>--mode must be practice, experiment or autonomous, got &apos;%1&apos;</source>
        <translation>--mode muss practice, experiment oder autonomous sein, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--rate needs a number &gt;= 0, got &apos;%1&apos;</source>
        <translation>--rate braucht eine Zahl &gt;= 0, erhalten: „%1“</translation>
    </message>
    <message>
        <source>Show the stored model NAME&apos;s predictions under the labels (needs --run); with --simulate --mode autonomous: the navigator&apos;s model.</source>
        <translation>Die Vorhersagen des gespeicherten Modells NAME unter den Labels zeigen (braucht --run); mit --simulate --mode autonomous: das Modell des Navigators.</translation>
    </message>
    <message>
        <source>With --simulate --mode autonomous: what the navigator&apos;s status comes from, model (with --model), truth or bumper, as tactile navigate --status.</source>
        <translation>Mit --simulate --mode autonomous: woher der Status des Navigators kommt, model (mit --model), truth oder bumper, wie bei tactile navigate --status.</translation>
    </message>
    <message>
        <source>--status needs --simulate and --mode autonomous</source>
        <translation>--status braucht --simulate und --mode autonomous</translation>
    </message>
    <message>
        <source>--status %1 takes no --model</source>
        <translation>--status %1 nimmt kein --model</translation>
    </message>
    <message>
        <source>--status must be model, truth or bumper, got &apos;%1&apos;</source>
        <translation>--status muss model, truth oder bumper sein, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--status model needs --model NAME</source>
        <translation>--status model braucht --model NAME</translation>
    </message>
    <message>
        <source>no display to open a window on (DISPLAY and WAYLAND_DISPLAY are not set). Run it in a desktop session, or with --screenshot FILE to render without a display; the command-line tool is tactile.</source>
        <translation>keine Anzeige, auf der sich ein Fenster öffnen ließe (DISPLAY und WAYLAND_DISPLAY sind nicht gesetzt). Starten Sie es in einer Desktop-Sitzung oder mit --screenshot FILE, um ohne Anzeige zu rendern; das Kommandozeilenwerkzeug ist tactile.</translation>
    </message>
    <message>
        <source>With --simulate --mode experiment: the seed of start and goal; --mode autonomous: the seed of the start (as tactile navigate --seeds); 0: the scene&apos;s own start and goal.</source>
        <translation>Mit --simulate --mode experiment: der Seed für Start und Ziel; --mode autonomous: der Seed des Starts (wie bei tactile navigate --seeds); 0: Start und Ziel der Szene selbst.</translation>
    </message>
    <message>
        <source>--seed needs a number &gt;= 0, got &apos;%1&apos;</source>
        <translation>--seed braucht eine Zahl &gt;= 0, erhalten: „%1“</translation>
    </message>
</context>
<context>
    <name>tactile::gui::ExperimentPanel</name>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Strategies</source>
        <translation>Strategien</translation>
    </message>
    <message>
        <source>Go Straight</source>
        <translation>Geradeaus fahren</translation>
    </message>
    <message>
        <source>Head to Destination</source>
        <translation>Zum Ziel fahren</translation>
    </message>
    <message>
        <source>Check Contact</source>
        <translation>Kontakt prüfen</translation>
    </message>
    <message>
        <source>Follow Wall</source>
        <translation>Wand folgen</translation>
    </message>
    <message>
        <source>Move through Wall</source>
        <translation>Durch die Wand fahren</translation>
    </message>
    <message>
        <source>Right U Turn</source>
        <translation>Rechtswende</translation>
    </message>
    <message>
        <source>Left U Turn</source>
        <translation>Linkswende</translation>
    </message>
    <message>
        <source>Hole, %1 wide</source>
        <translation>Lücke, %1 breit</translation>
    </message>
    <message>
        <source>Undecided</source>
        <translation>Unentschieden</translation>
    </message>
</context>
<context>
    <name>tactile::gui::HistoryView</name>
    <message>
        <source>labelled</source>
        <translation>beschriftet</translation>
    </message>
    <message>
        <source>moved</source>
        <translation>verschoben</translation>
    </message>
    <message>
        <source>deleted</source>
        <translation>gelöscht</translation>
    </message>
    <message>
        <source>undone</source>
        <translation>rückgängig gemacht</translation>
    </message>
    <message>
        <source>redone</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <source>imported</source>
        <translation>importiert</translation>
    </message>
    <message>
        <source>from truth</source>
        <translation>aus der Wahrheit</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>zurückgesetzt</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>Time (UTC)</source>
        <translation>Zeit (UTC)</translation>
    </message>
    <message>
        <source>Annotator</source>
        <translation>Annotator</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <source>Open a label set and a run to see who changed its labels.</source>
        <translation>Öffnen Sie ein Label-Set und einen Lauf, um zu sehen, wer seine Labels geändert hat.</translation>
    </message>
    <message>
        <source>No edit of these labels is recorded yet.</source>
        <translation>Für diese Labels ist noch keine Änderung verzeichnet.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <source>%1 %2-%3 by %4</source>
        <translation>%1 %2-%3 von %4</translation>
    </message>
    <message>
        <source>The steps were unlabelled before.</source>
        <translation>Die Schritte waren vorher unbeschriftet.</translation>
    </message>
    <message>
        <source>Before: %1</source>
        <translation>Vorher: %1</translation>
    </message>
    <message>
        <source>%1 %2-%3: %4 (%5)</source>
        <translation>%1 %2-%3: %4 (%5)</translation>
    </message>
    <message>
        <source>cleared or several</source>
        <translation>gelöscht oder mehrere</translation>
    </message>
    <message>
        <source>One edit of set &apos;%1&apos; on this run.</source>
        <translation>Eine Änderung von Set &apos;%1&apos; an diesem Lauf.</translation>
    </message>
    <message>
        <source>%1 edits of set &apos;%2&apos; on this run, newest first.</source>
        <translation>%1 Änderungen von Set &apos;%2&apos; an diesem Lauf, neueste zuerst.</translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelModel</name>
    <message>
        <source>Label steps %1-%2 as %3</source>
        <translation>Schritte %1–%2 als %3 labeln</translation>
    </message>
    <message>
        <source>Move %1 segment to steps %2-%3</source>
        <translation>%1-Segment auf Schritte %2–%3 verschieben</translation>
    </message>
    <message>
        <source>Delete segment</source>
        <translation>Segment löschen</translation>
    </message>
    <message>
        <source> The run&apos;s labels are reloaded.</source>
        <translation> Die Labels des Laufs werden neu geladen.</translation>
    </message>
    <message>
        <source>%1 changed %2 steps %3-%4 (%5)</source>
        <translation>%1 hat %2 Schritte %3-%4 geändert (%5)</translation>
    </message>
    <message>
        <source>someone</source>
        <translation>jemand</translation>
    </message>
    <message>
        <source>Label steps %1-%2 from the model</source>
        <translation>Schritte %1-%2 mit dem Modell beschriften</translation>
    </message>
    <message>
        <source>no chosen model covers %1: choose the group of a model (Learn &gt; Show Predictions shows which groups each covers)</source>
        <translation>kein gewähltes Modell deckt %1 ab: wählen Sie eine Gruppe eines Modells (Lernen &gt; Vorhersagen zeigen nennt die Gruppen jedes Modells)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelPanelView</name>
    <message>
        <source>Label set</source>
        <translation>Labelsatz</translation>
    </message>
    <message>
        <source>The label set being edited; choose another to open it</source>
        <translation>Der bearbeitete Labelsatz; einen anderen wählen, um ihn zu öffnen</translation>
    </message>
    <message>
        <source>New...</source>
        <translation>Neu...</translation>
    </message>
    <message>
        <source>Save As...</source>
        <translation>Speichern unter...</translation>
    </message>
    <message>
        <source>Import...</source>
        <translation>Importieren...</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Exportieren...</translation>
    </message>
    <message>
        <source>Apply to</source>
        <translation>Anwenden auf</translation>
    </message>
    <message>
        <source>Selected group</source>
        <translation>Gewählte Gruppe</translation>
    </message>
    <message>
        <source>Checked groups</source>
        <translation>Angehakte Gruppen</translation>
    </message>
    <message>
        <source>Groups in contact</source>
        <translation>Gruppen mit Kontakt</translation>
    </message>
    <message>
        <source>Label the %1 group (with &quot;Checked groups&quot;)</source>
        <translation>Die Gruppe %1 labeln (mit „Angehakte Gruppen“)</translation>
    </message>
    <message>
        <source>Classes (keys 1-5)</source>
        <translation>Klassen (Tasten 1–5)</translation>
    </message>
    <message>
        <source>Label the selected steps as %1 (key %2)</source>
        <translation>Die gewählten Schritte als %1 labeln (Taste %2)</translation>
    </message>
    <message>
        <source>At the cursor</source>
        <translation>Am Cursor</translation>
    </message>
    <message>
        <source>Delete segment (Del)</source>
        <translation>Segment löschen (Entf)</translation>
    </message>
    <message>
        <source>Selection:</source>
        <translation>Auswahl:</translation>
    </message>
    <message>
        <source>Segment:</source>
        <translation>Segment:</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>Agree</source>
        <translation>Übereinst.</translation>
    </message>
    <message>
        <source>Kappa</source>
        <translation>Kappa</translation>
    </message>
    <message>
        <source>Open a run first.</source>
        <translation>Zuerst einen Lauf öffnen.</translation>
    </message>
    <message>
        <source>Create or open a label set first.</source>
        <translation>Zuerst einen Labelsatz anlegen oder öffnen.</translation>
    </message>
    <message>
        <source>No segment of the selected group under the cursor.</source>
        <translation>Kein Segment der gewählten Gruppe unter dem Cursor.</translation>
    </message>
    <message>
        <source>(no label set)</source>
        <translation>(kein Labelsatz)</translation>
    </message>
    <message>
        <source>New label set</source>
        <translation>Neuer Labelsatz</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>No label set is open.</source>
        <translation>Kein Labelsatz geöffnet.</translation>
    </message>
    <message>
        <source>Save label set as</source>
        <translation>Labelsatz speichern unter</translation>
    </message>
    <message>
        <source>Name of the copy:</source>
        <translation>Name der Kopie:</translation>
    </message>
    <message>
        <source> copy</source>
        <translation> Kopie</translation>
    </message>
    <message>
        <source>Import labels</source>
        <translation>Labels importieren</translation>
    </message>
    <message>
        <source>Label files (*.csv *.json);;All files (*)</source>
        <translation>Label-Dateien (*.csv *.json);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s)</source>
        <translation>
            <numerusform>%n Segment importiert</numerusform>
            <numerusform>%n Segmente importiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Export labels</source>
        <translation>Labels exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv);;JSON (*.json)</source>
        <translation>CSV (*.csv);;JSON (*.json)</translation>
    </message>
    <message>
        <source>Exported %1 to %2</source>
        <translation>%1 nach %2 exportiert</translation>
    </message>
    <message numerus="yes">
        <source>steps %1-%2 (%n step(s))</source>
        <translation>
            <numerusform>Schritte %1–%2 (%n Schritt)</numerusform>
            <numerusform>Schritte %1–%2 (%n Schritte)</numerusform>
        </translation>
    </message>
    <message>
        <source>none (an edit labels the current step)</source>
        <translation>keine (eine Änderung labelt den aktuellen Schritt)</translation>
    </message>
    <message>
        <source>%1: unlabelled</source>
        <translation>%1: ohne Label</translation>
    </message>
    <message>
        <source>%1: %2, steps %3-%4</source>
        <translation>%1: %2, Schritte %3–%4</translation>
    </message>
    <message>
        <source>Compare the labels with the run&apos;s truth or with another label set (another annotator)</source>
        <translation>Die Labels mit der Ground Truth des Laufs oder mit einem anderen Labelsatz (eines anderen Annotators) vergleichen</translation>
    </message>
    <message>
        <source>Chance</source>
        <translation>Zufall</translation>
    </message>
    <message>
        <source>Share of the steps both sides label on which they give the same class</source>
        <translation>Anteil der von beiden Seiten gelabelten Schritte, auf denen beide dieselbe Klasse vergeben</translation>
    </message>
    <message>
        <source>Agreement expected by chance from each side&apos;s class shares</source>
        <translation>Aus den Klassenanteilen beider Seiten zufällig zu erwartende Übereinstimmung</translation>
    </message>
    <message>
        <source>Cohen&apos;s kappa = (agree - chance) / (100 % - chance): 0 when the agreement is no better than chance, 1 when perfect; &apos;-&apos; when chance is 100 % (one class throughout)</source>
        <translation>Cohens Kappa = (Übereinst. − Zufall) / (100 % − Zufall): 0, wenn die Übereinstimmung nicht besser als Zufall ist, 1 bei vollständiger Übereinstimmung; „-“, wenn der Zufall 100 % beträgt (durchgehend eine Klasse)</translation>
    </message>
    <message>
        <source>Agreement with</source>
        <translation>Übereinstimmung mit</translation>
    </message>
    <message>
        <source>truth</source>
        <translation>Ground Truth</translation>
    </message>
    <message>
        <source>label set %1</source>
        <translation>Labelsatz %1</translation>
    </message>
    <message>
        <source>No step is labelled on both sides</source>
        <translation>Kein Schritt ist auf beiden Seiten gelabelt</translation>
    </message>
    <message numerus="yes">
        <source>Undefined: both sides use one and the same class on all %n step(s), so chance agreement is 100 %</source>
        <translation>
            <numerusform>Undefiniert: Beide Seiten vergeben auf %n Schritt ein und dieselbe Klasse, die zufällige Übereinstimmung ist also 100 %</numerusform>
            <numerusform>Undefiniert: Beide Seiten vergeben auf allen %n Schritten ein und dieselbe Klasse, die zufällige Übereinstimmung ist also 100 %</numerusform>
        </translation>
    </message>
    <message>
        <source>No group is in contact here: nothing to label.</source>
        <translation>Hier berührt keine Gruppe etwas: nichts zu beschriften.</translation>
    </message>
    <message>
        <source>No group to label: tick a group.</source>
        <translation>Keine Gruppe zu beschriften: eine Gruppe ankreuzen.</translation>
    </message>
    <message>
        <source>Labelled steps %1-%2 as %3 in %4</source>
        <translation>Schritte %1-%2 als %3 beschriftet in %4</translation>
    </message>
    <message>
        <source>%1 of %2 steps agree (%3). Two annotators labelling at random with these class shares would agree on %4. Kappa %5 says how much better than chance they agree: 1 fully, 0 no better than chance.</source>
        <translation>%1 von %2 Schritten stimmen überein (%3). Zwei Annotatoren, die zufällig mit diesen Klassenanteilen beschriften, stimmten bei %4 überein. Kappa %5 sagt, wie viel besser als der Zufall die Übereinstimmung ist: 1 vollständig, 0 nicht besser als Zufall.</translation>
    </message>
</context>
<context>
    <name>tactile::gui::MainWindow</name>
    <message>
        <source>Runs</source>
        <translation>Läufe</translation>
    </message>
    <message>
        <source>Route</source>
        <translation>Route</translation>
    </message>
    <message>
        <source>Labels</source>
        <translation>Labels</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open Database...</source>
        <translation>Datenbank ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>&amp;New Database...</source>
        <translation>&amp;Neue Datenbank...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Import Runs...</source>
        <translation>Läufe &amp;importieren...</translation>
    </message>
    <message>
        <source>Export &amp;Labels...</source>
        <translation>&amp;Labels exportieren...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Label as %1</source>
        <translation>Als %1 labeln</translation>
    </message>
    <message>
        <source>&amp;Delete Segment</source>
        <translation>Segment &amp;löschen</translation>
    </message>
    <message>
        <source>Move Segment Start Left</source>
        <translation>Segmentanfang nach links</translation>
    </message>
    <message>
        <source>Move Segment Start Right</source>
        <translation>Segmentanfang nach rechts</translation>
    </message>
    <message>
        <source>Move Segment End Left</source>
        <translation>Segmentende nach links</translation>
    </message>
    <message>
        <source>Move Segment End Right</source>
        <translation>Segmentende nach rechts</translation>
    </message>
    <message>
        <source>Clear Selection</source>
        <translation>Auswahl aufheben</translation>
    </message>
    <message>
        <source>&amp;Go</source>
        <translation>&amp;Gehe zu</translation>
    </message>
    <message>
        <source>Next Step</source>
        <translation>Nächster Schritt</translation>
    </message>
    <message>
        <source>Previous Step</source>
        <translation>Vorheriger Schritt</translation>
    </message>
    <message>
        <source>Forward 10 Steps</source>
        <translation>10 Schritte vor</translation>
    </message>
    <message>
        <source>Back 10 Steps</source>
        <translation>10 Schritte zurück</translation>
    </message>
    <message>
        <source>Forward 100 Steps</source>
        <translation>100 Schritte vor</translation>
    </message>
    <message>
        <source>Back 100 Steps</source>
        <translation>100 Schritte zurück</translation>
    </message>
    <message>
        <source>Forward One Screen</source>
        <translation>Eine Bildschirmbreite vor</translation>
    </message>
    <message>
        <source>Back One Screen</source>
        <translation>Eine Bildschirmbreite zurück</translation>
    </message>
    <message>
        <source>First Step</source>
        <translation>Erster Schritt</translation>
    </message>
    <message>
        <source>Last Step</source>
        <translation>Letzter Schritt</translation>
    </message>
    <message>
        <source>Play / Pause</source>
        <translation>Abspielen / Pause</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene</source>
        <translation>Roboter-Nahansicht / ganze Szene</translation>
    </message>
    <message>
        <source>Colour Route by Label</source>
        <translation>Route nach Label einfärben</translation>
    </message>
    <message>
        <source>Heatmap: Normal</source>
        <translation>Heatmap: Normalkraft</translation>
    </message>
    <message>
        <source>Heatmap: Shear</source>
        <translation>Heatmap: Scherkraft</translation>
    </message>
    <message>
        <source>Heatmap: Magnitude</source>
        <translation>Heatmap: Betrag</translation>
    </message>
    <message>
        <source>Zoom to Whole Run</source>
        <translation>Ganzen Lauf zeigen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Tactile Workbench</source>
        <translation>&amp;Über Tactile Workbench</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Open or create a database before importing runs.</source>
        <translation>Vor dem Import von Läufen eine Datenbank öffnen oder anlegen.</translation>
    </message>
    <message numerus="yes">
        <source>Importing %n run file(s)...</source>
        <translation>
            <numerusform>%n Laufdatei wird importiert...</numerusform>
            <numerusform>%n Laufdateien werden importiert...</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n run(s)</source>
        <translation>
            <numerusform>%n Lauf importiert</numerusform>
            <numerusform>%n Läufe importiert</numerusform>
        </translation>
    </message>
    <message>
        <source>; cancelled</source>
        <translation>; abgebrochen</translation>
    </message>
    <message numerus="yes">
        <source>; %n file(s) not imported: </source>
        <translation>
            <numerusform>; %n Datei nicht importiert: </numerusform>
            <numerusform>; %n Dateien nicht importiert: </numerusform>
        </translation>
    </message>
    <message>
        <source>New database</source>
        <translation>Neue Datenbank</translation>
    </message>
    <message>
        <source>Tactile databases (*.db);;All files (*)</source>
        <translation>Tactile-Datenbanken (*.db);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open database</source>
        <translation>Datenbank öffnen</translation>
    </message>
    <message>
        <source>Tactile databases (*.db *.sqlite);;All files (*)</source>
        <translation>Tactile-Datenbanken (*.db *.sqlite);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Import runs</source>
        <translation>Läufe importieren</translation>
    </message>
    <message>
        <source>Run files (*.csv);;All files (*)</source>
        <translation>Laufdateien (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>Tactile Workbench</source>
        <translation>Tactile Workbench</translation>
    </message>
    <message>
        <source>  |  selected %1-%2</source>
        <translation>  |  ausgewählt %1–%2</translation>
    </message>
    <message>
        <source>No run open</source>
        <translation>Kein Lauf geöffnet</translation>
    </message>
    <message>
        <source>No database open</source>
        <translation>Keine Datenbank geöffnet</translation>
    </message>
    <message>
        <source>Label set: %1</source>
        <translation>Labelsatz: %1</translation>
    </message>
    <message>
        <source>No label set</source>
        <translation>Kein Labelsatz</translation>
    </message>
    <message>
        <source>About Tactile Workbench</source>
        <translation>Über Tactile Workbench</translation>
    </message>
    <message>
        <source>Tactile Workbench %1
Research workbench for tactile-based mobile-robot navigation.</source>
        <translation>Tactile Workbench %1
Forschungsumgebung für die taktile Navigation mobiler Roboter.</translation>
    </message>
    <message>
        <source>&amp;Learn</source>
        <translation>&amp;Lernen</translation>
    </message>
    <message>
        <source>&amp;Train and Sweep...</source>
        <translation>&amp;Trainieren und Sweep...</translation>
    </message>
    <message>
        <source>Open &amp;Sweep Results...</source>
        <translation>&amp;Sweep-Ergebnisse öffnen...</translation>
    </message>
    <message>
        <source>&amp;Export Model...</source>
        <translation>Modell &amp;exportieren...</translation>
    </message>
    <message>
        <source>&amp;Import Model...</source>
        <translation>Modell &amp;importieren...</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>A sweep or training is running. Cancel it and quit? Finished sweep cells stay stored.</source>
        <translation>Ein Sweep oder Training läuft. Abbrechen und beenden? Fertige Sweep-Zellen bleiben gespeichert.</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored</source>
        <translation>Modell „%1“ gespeichert</translation>
    </message>
    <message>
        <source>Open a database first</source>
        <translation>Zuerst eine Datenbank öffnen</translation>
    </message>
    <message>
        <source>The database has no sweep yet: Learn &gt; Train and Sweep</source>
        <translation>Die Datenbank hat noch keinen Sweep: Lernen &gt; Trainieren und Sweep</translation>
    </message>
    <message>
        <source>%1: %2 (%3 cells, %4)</source>
        <translation>%1: %2 (%3 Zellen, %4)</translation>
    </message>
    <message>
        <source>Open Sweep Results</source>
        <translation>Sweep-Ergebnisse öffnen</translation>
    </message>
    <message>
        <source>Sweep:</source>
        <translation>Sweep:</translation>
    </message>
    <message>
        <source>The database has no model yet</source>
        <translation>Die Datenbank hat noch kein Modell</translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation>Modell exportieren</translation>
    </message>
    <message>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation>Modelldateien (*.json)</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; written to %2</source>
        <translation>Modell „%1“ nach %2 geschrieben</translation>
    </message>
    <message>
        <source>Import Model</source>
        <translation>Modell importieren</translation>
    </message>
    <message>
        <source>Store as:</source>
        <translation>Speichern als:</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored from %2</source>
        <translation>Modell „%1“ aus %2 gespeichert</translation>
    </message>
    <message>
        <source>Predictions: %1</source>
        <translation>Vorhersagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>Predictions shown: %n step(s) disagree with the labels (N: next)</source>
        <translation>
            <numerusform>Vorhersagen angezeigt: %n Schritt weicht von den Labels ab (N: nächster)</numerusform>
            <numerusform>Vorhersagen angezeigt: %n Schritte weichen von den Labels ab (N: nächster)</numerusform>
        </translation>
    </message>
    <message>
        <source>Show &amp;Predictions...</source>
        <translation>&amp;Vorhersagen anzeigen...</translation>
    </message>
    <message>
        <source>&amp;Hide Predictions</source>
        <translation>Vorhersagen &amp;ausblenden</translation>
    </message>
    <message>
        <source>&amp;Next Disagreement</source>
        <translation>&amp;Nächste Abweichung</translation>
    </message>
    <message>
        <source>Pre&amp;vious Disagreement</source>
        <translation>&amp;Vorherige Abweichung</translation>
    </message>
    <message>
        <source>Open a run first</source>
        <translation>Zuerst einen Lauf öffnen</translation>
    </message>
    <message>
        <source>The database has no model yet: Learn &gt; Train and Sweep</source>
        <translation>Die Datenbank hat noch kein Modell: Lernen &gt; Trainieren und Sweep</translation>
    </message>
    <message>
        <source>No predictions shown: Learn &gt; Show Predictions</source>
        <translation>Keine Vorhersagen angezeigt: Lernen &gt; Vorhersagen anzeigen</translation>
    </message>
    <message>
        <source>The model agrees with the labels everywhere</source>
        <translation>Das Modell stimmt überall mit den Labels überein</translation>
    </message>
    <message>
        <source>Step %1, group %2: the model says %3 (%4 %), the label %5</source>
        <translation>Schritt %1, Gruppe %2: das Modell sagt %3 (%4 %), das Label %5</translation>
    </message>
    <message>
        <source>Importing runs...</source>
        <translation>Läufe werden importiert...</translation>
    </message>
    <message>
        <source>Not a run file, folder or database: %1</source>
        <translation>Weder Laufdatei noch Ordner noch Datenbank: %1</translation>
    </message>
    <message numerus="yes">
        <source>Drop one database at a time (%n dropped).</source>
        <translation>
            <numerusform>Bitte nur eine Datenbank auf einmal ablegen (%n abgelegt).</numerusform>
            <numerusform>Bitte nur eine Datenbank auf einmal ablegen (%n abgelegt).</numerusform>
        </translation>
    </message>
    <message>
        <source>Navigator</source>
        <translation>Navigator</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Preferences saved</source>
        <translation>Einstellungen gespeichert</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Einstellungen...</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>Step %1 of %2 steps</source>
        <translation>Schritt %1 von %2 Schritten</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>New &amp;Simulation...</source>
        <translation>Neue &amp;Simulation...</translation>
    </message>
    <message>
        <source>Import &amp;MCAP...</source>
        <translation>&amp;MCAP importieren...</translation>
    </message>
    <message>
        <source>Export &amp;Run</source>
        <translation>&amp;Lauf exportieren</translation>
    </message>
    <message>
        <source>&amp;MCAP...</source>
        <translation>&amp;MCAP...</translation>
    </message>
    <message>
        <source>Drop one MCAP file at a time, on its own.</source>
        <translation>Bitte nur eine MCAP-Datei auf einmal und allein ablegen.</translation>
    </message>
    <message>
        <source>An MCAP export or import is already running</source>
        <translation>Ein MCAP-Export oder -Import läuft bereits</translation>
    </message>
    <message>
        <source>Exporting &apos;%1&apos; to %2...</source>
        <translation>„%1“ wird nach %2 exportiert...</translation>
    </message>
    <message>
        <source>MCAP export cancelled</source>
        <translation>MCAP-Export abgebrochen</translation>
    </message>
    <message>
        <source>Export Run as MCAP</source>
        <translation>Lauf als MCAP exportieren</translation>
    </message>
    <message numerus="yes">
        <source>Run written to %1 (%n step(s))</source>
        <translation>
            <numerusform>Lauf nach %1 geschrieben (%n Schritt)</numerusform>
            <numerusform>Lauf nach %1 geschrieben (%n Schritte)</numerusform>
        </translation>
    </message>
    <message>
        <source>Import MCAP</source>
        <translation>MCAP importieren</translation>
    </message>
    <message>
        <source>MCAP files (*.mcap);;All files (*)</source>
        <translation>MCAP-Dateien (*.mcap);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Importing %1...</source>
        <translation>%1 wird importiert...</translation>
    </message>
    <message numerus="yes">
        <source>Imported run &apos;%1&apos; (%n step(s))</source>
        <translation>
            <numerusform>Lauf „%1“ importiert (%n Schritt)</numerusform>
            <numerusform>Lauf „%1“ importiert (%n Schritte)</numerusform>
        </translation>
    </message>
    <message>
        <source>Undone: %1</source>
        <translation>Rückgängig gemacht: %1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>Wiederhergestellt: %1</translation>
    </message>
    <message>
        <source>Labels changed by others: %1</source>
        <translation>Von anderen geänderte Labels: %1</translation>
    </message>
    <message>
        <source>Reconnected to %1</source>
        <translation>Wieder verbunden mit %1</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>Open &amp;Server...</source>
        <translation>&amp;Server öffnen...</translation>
    </message>
    <message>
        <source>Open Server</source>
        <translation>Server öffnen</translation>
    </message>
    <message>
        <source>PostgreSQL address, e.g. postgresql://anna@lab-server/tactile
(the password is asked when the server wants one, or comes from ~/.pgpass)</source>
        <translation>PostgreSQL-Adresse, z. B. postgresql://anna@lab-server/tactile
(das Passwort wird erfragt, wenn der Server eines verlangt, oder kommt aus ~/.pgpass)</translation>
    </message>
    <message>
        <source>%1 is not a server address (postgresql://USER@HOST/DATABASE)</source>
        <translation>%1 ist keine Serveradresse (postgresql://BENUTZER@HOST/DATENBANK)</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>Password for %1:</source>
        <translation>Passwort für %1:</translation>
    </message>
    <message>
        <source>Assign Run</source>
        <translation>Lauf zuweisen</translation>
    </message>
    <message>
        <source>Annotator to assign %1 to:</source>
        <translation>Annotator, dem %1 zugewiesen wird:</translation>
    </message>
    <message>
        <source>Set your annotator name in Preferences first.</source>
        <translation>Geben Sie zuerst Ihren Annotator-Namen in den Einstellungen an.</translation>
    </message>
    <message>
        <source>%1 assigned to %2: %3</source>
        <translation>%1 an %2 zugewiesen: %3</translation>
    </message>
    <message>
        <source>Your role on this database: %1</source>
        <translation>Ihre Rolle in dieser Datenbank: %1</translation>
    </message>
    <message>
        <source>admin</source>
        <translation>Administrator</translation>
    </message>
    <message>
        <source>researcher</source>
        <translation>Forscher</translation>
    </message>
    <message>
        <source>annotator</source>
        <translation>Annotator</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>nur lesen</translation>
    </message>
    <message>
        <source>&amp;Label from Model</source>
        <translation>Mit Modell &amp;beschriften</translation>
    </message>
    <message>
        <source>Open a run and a label set first.</source>
        <translation>Öffnen Sie zuerst einen Lauf und ein Label-Set.</translation>
    </message>
    <message>
        <source>Show a model&apos;s predictions first (Learn &gt; Show Predictions): their model&apos;s decisions are what Label from Model writes.</source>
        <translation>Zeigen Sie zuerst die Vorhersagen eines Modells (Lernen &gt; Vorhersagen zeigen): dessen Entscheidungen schreibt „Mit Modell beschriften“.</translation>
    </message>
    <message>
        <source>Steps %1-%2 labelled from the model (Undo takes it back)</source>
        <translation>Schritte %1-%2 mit dem Modell beschriftet (Rückgängig nimmt es zurück)</translation>
    </message>
    <message>
        <source>Next &amp;Doubt</source>
        <translation>Nächster &amp;Zweifel</translation>
    </message>
    <message>
        <source>The model is at least %1 % sure everywhere</source>
        <translation>Das Modell ist überall mindestens zu %1 % sicher</translation>
    </message>
    <message>
        <source>Step %1, group %2: the model is unsure (%3 % %4)</source>
        <translation>Schritt %1, Gruppe %2: das Modell ist unsicher (%3 % %4)</translation>
    </message>
    <message>
        <source>Lost the connection to the database; trying again every 3 seconds, and edits are not stored meanwhile (%1)</source>
        <translation>Verbindung zur Datenbank verloren; neuer Versuch alle 3 Sekunden, Änderungen werden bis dahin nicht gespeichert (%1)</translation>
    </message>
    <message>
        <source>Predictions shown; this run has no labels in the set yet (Ctrl+L labels the steps in view from the model)</source>
        <translation>Vorhersagen angezeigt; dieser Lauf hat im Labelsatz noch keine Labels (Strg+L beschriftet die sichtbaren Schritte aus dem Modell)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::McapExportDialog</name>
    <message>
        <source>Export Run as MCAP</source>
        <translation>Lauf als MCAP exportieren</translation>
    </message>
    <message>
        <source>Run:</source>
        <translation>Lauf:</translation>
    </message>
    <message>
        <source>Label sets:</source>
        <translation>Labelsätze:</translation>
    </message>
    <message>
        <source>none in this database</source>
        <translation>keine in dieser Datenbank</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keins)</translation>
    </message>
    <message>
        <source>The model&apos;s online decisions go on /decisions/MODEL</source>
        <translation>Die Online-Entscheidungen des Modells kommen auf /decisions/MODEL</translation>
    </message>
    <message>
        <source>Model decisions:</source>
        <translation>Modellentscheidungen:</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>Opens in Foxglove and Lichtblick: the readings, pose, command, truth, the chosen label sets and the model&apos;s decisions, one message per step, and the scene&apos;s walls.</source>
        <translation>Öffnet sich in Foxglove und Lichtblick: Messwerte, Pose, Befehl, Wahrheit, die gewählten Labelsätze und die Entscheidungen des Modells, eine Nachricht je Schritt, und die Wände der Szene.</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>MCAP files (*.mcap);;All files (*)</source>
        <translation>MCAP-Dateien (*.mcap);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::McapMappingDialog</name>
    <message>
        <source>Import ROS 2 Bag</source>
        <translation>ROS-2-Bag importieren</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; is not an export of this program. Choose which of its topics make the run: one step per message on the tactile topic; pose and command are the latest messages before it.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; ist kein Export dieses Programms. Wählen Sie, welche seiner Topics den Lauf bilden: ein Schritt je Nachricht auf dem Tast-Topic; Pose und Befehl sind die letzten Nachrichten davor.</translation>
    </message>
    <message>
        <source>Topic</source>
        <translation>Topic</translation>
    </message>
    <message>
        <source>Schema</source>
        <translation>Schema</translation>
    </message>
    <message>
        <source>Message encoding</source>
        <translation>Nachrichtenkodierung</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Nachrichten</translation>
    </message>
    <message>
        <source>44 normals, then 44 shears</source>
        <translation>44 Normalwerte, dann 44 Scherwerte</translation>
    </message>
    <message>
        <source>interleaved: n0, s0, n1, s1, ...</source>
        <translation>verschränkt: n0, s0, n1, s1, ...</translation>
    </message>
    <message>
        <source>Scene units per bag unit: 1000 for a bag in metres (scenes are in mm)</source>
        <translation>Szeneneinheiten je Bag-Einheit: 1000 für ein Bag in Metern (Szenen sind in mm)</translation>
    </message>
    <message>
        <source>Tactile readings:</source>
        <translation>Tastwerte:</translation>
    </message>
    <message>
        <source>Layout of the 88 values:</source>
        <translation>Anordnung der 88 Werte:</translation>
    </message>
    <message>
        <source>Pose:</source>
        <translation>Pose:</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Befehl:</translation>
    </message>
    <message>
        <source>Blocked flag:</source>
        <translation>Blockiert-Flag:</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Maßstab:</translation>
    </message>
    <message>
        <source>Run name:</source>
        <translation>Laufname:</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Channels in the file:</source>
        <translation>Kanäle in der Datei:</translation>
    </message>
</context>
<context>
    <name>tactile::gui::ModelPickerDialog</name>
    <message>
        <source>Show Predictions</source>
        <translation>Vorhersagen anzeigen</translation>
    </message>
    <message>
        <source>A model per group</source>
        <translation>Ein Modell je Gruppe</translation>
    </message>
    <message>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <source>The timeline shows each group&apos;s predicted class under its labels, pale where the model is unsure, and marks where it disagrees with the labels (N: next disagreement).</source>
        <translation>Die Zeitleiste zeigt die vorhergesagte Klasse jeder Gruppe unter ihren Labels, blass, wo das Modell unsicher ist, und markiert Abweichungen von den Labels (N: nächste Abweichung).</translation>
    </message>
    <message>
        <source>%1 (all groups)</source>
        <translation>%1 (alle Gruppen)</translation>
    </message>
    <message>
        <source>%1 (%2 only)</source>
        <translation>%1 (nur %2)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorPanelView</name>
    <message>
        <source>This run has no navigator columns. Runs written by &apos;tactile navigate&apos; have them.</source>
        <translation>Dieser Lauf hat keine Navigator-Spalten. Von „tactile navigate“ geschriebene Läufe haben sie.</translation>
    </message>
    <message>
        <source>Command set:</source>
        <translation>Befehlssatz:</translation>
    </message>
    <message>
        <source>Current control mode:</source>
        <translation>Aktueller Steuermodus:</translation>
    </message>
    <message>
        <source>Status:</source>
        <translation>Status:</translation>
    </message>
    <message>
        <source>Status-%1:</source>
        <translation>Status-%1:</translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorStripView</name>
    <message>
        <source>strategy</source>
        <translation>Strategie</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation>Schritt %1: %2</translation>
    </message>
</context>
<context>
    <name>tactile::gui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Follow the system</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>e.g. your initials</source>
        <translation>z. B. Ihre Initialen</translation>
    </message>
    <message>
        <source>Stored with every label segment you write and in label exports (annotator column)</source>
        <translation>Wird mit jedem Label-Segment, das Sie schreiben, und in Label-Exporten gespeichert (Spalte annotator)</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Height of each label, truth and model row in the timelines</source>
        <translation>Höhe jeder Label-, Ground-Truth- und Modellzeile in den Zeitleisten</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>A new language applies at the next start.</source>
        <translation>Eine neue Sprache gilt ab dem nächsten Start.</translation>
    </message>
    <message>
        <source>&amp;Annotator:</source>
        <translation>&amp;Annotator:</translation>
    </message>
    <message>
        <source>Timeline &amp;row height:</source>
        <translation>&amp;Zeilenhöhe der Zeitleisten:</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Learn &gt; Next Doubt (D) stops where the model&apos;s posterior of its own prediction is below this</source>
        <translation>Lernen &gt; Nächster Zweifel (D) hält, wo die A-posteriori-Wahrscheinlichkeit der eigenen Vorhersage des Modells darunter liegt</translation>
    </message>
    <message>
        <source>Model &amp;unsure below:</source>
        <translation>Modell &amp;unsicher unter:</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RouteView</name>
    <message>
        <source>%1 units to the goal</source>
        <translation>%1 Einheiten bis zum Ziel</translation>
    </message>
    <message>
        <source>No run open</source>
        <translation>Kein Lauf geöffnet</translation>
    </message>
    <message>
        <source>Whole scene (M: close-up)</source>
        <translation>Ganze Szene (M: Nahansicht)</translation>
    </message>
    <message>
        <source>Close-up (M: whole scene)</source>
        <translation>Nahansicht (M: ganze Szene)</translation>
    </message>
    <message>
        <source>hole %1</source>
        <translation>Lücke %1</translation>
    </message>
    <message>
        <source>hole %1 wide</source>
        <translation>Lücke %1 breit</translation>
    </message>
    <message>
        <source>Zoomed %1x (double click: whole scene)</source>
        <translation>Zoom %1x (Doppelklick: ganze Szene)</translation>
    </message>
    <message>
        <source>Close-up zoomed %1x (double click: close-up)</source>
        <translation>Nahansicht, Zoom %1x (Doppelklick: Nahansicht)</translation>
    </message>
    <message>
        <source>■ hole N: a gap N units wide that the model felt on one side</source>
        <translation>■ Lücke N: eine N Einheiten breite Lücke, die das Modell auf einer Seite gefühlt hat</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListModel</name>
    <message>
        <source>%1
imported from %2</source>
        <translation>%1
importiert aus %2</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Subject</source>
        <translation>Proband</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Labelled</source>
        <translation>Gelabelt</translation>
    </message>
    <message>
        <source>to do</source>
        <translation>zu erledigen</translation>
    </message>
    <message>
        <source>labelled</source>
        <translation>beschriftet</translation>
    </message>
    <message>
        <source>reviewed</source>
        <translation>geprüft</translation>
    </message>
    <message>
        <source>Assigned</source>
        <translation>Zugewiesen</translation>
    </message>
    <message>
        <source>%1 % (model %2 %)</source>
        <translation>%1 % (Modell %2 %)</translation>
    </message>
    <message>
        <source>Steps x groups labelled in the current set: %1 % by people, %2 % by a model</source>
        <translation>Beschriftete Schritte x Gruppen im aktuellen Set: %1 % von Menschen, %2 % von einem Modell</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListView</name>
    <message>
        <source>Filter runs by name, scene, subject or outcome</source>
        <translation>Läufe nach Name, Szene, Proband oder Ergebnis filtern</translation>
    </message>
    <message>
        <source>Assigned to me</source>
        <translation>Mir zugewiesen</translation>
    </message>
    <message>
        <source>Only the runs assigned to the annotator named in Preferences</source>
        <translation>Nur die Läufe, die dem in den Einstellungen genannten Annotator zugewiesen sind</translation>
    </message>
    <message>
        <source>Assign to...</source>
        <translation>Zuweisen an...</translation>
    </message>
    <message>
        <source>My Assignment: To Do</source>
        <translation>Meine Zuweisung: zu erledigen</translation>
    </message>
    <message>
        <source>My Assignment: Labelled</source>
        <translation>Meine Zuweisung: beschriftet</translation>
    </message>
    <message>
        <source>My Assignment: Reviewed</source>
        <translation>Meine Zuweisung: geprüft</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SignalBarsView</name>
    <message>
        <source>normal</source>
        <translation>Normalkraft</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>Scherkraft</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimSession</name>
    <message>
        <source>An experiment run needs the subject&apos;s name.</source>
        <translation>Ein Experimentlauf braucht den Namen des Probanden.</translation>
    </message>
    <message>
        <source>A subject&apos;s name must be one line.</source>
        <translation>Der Name eines Probanden muss einzeilig sein.</translation>
    </message>
    <message>
        <source>Autonomous mode needs a driver.</source>
        <translation>Der autonome Modus braucht einen Fahrer.</translation>
    </message>
    <message>
        <source>The step length must be in (0, 1] seconds.</source>
        <translation>Die Schrittlänge muss in (0, 1] Sekunden liegen.</translation>
    </message>
    <message>
        <source>The time limit must be positive.</source>
        <translation>Das Zeitlimit muss positiv sein.</translation>
    </message>
    <message>
        <source>practice</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <source>autonomous</source>
        <translation>autonom</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimWindow</name>
    <message>
        <source>Run %1 ended: %2</source>
        <translation>Lauf %1 beendet: %2</translation>
    </message>
    <message>
        <source>Tactile Simulator</source>
        <translation>Taktiler Simulator</translation>
    </message>
    <message>
        <source>Practice</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <source>Autonomous</source>
        <translation>Autonom</translation>
    </message>
    <message>
        <source>needed in experiment mode</source>
        <translation>im Experimentmodus nötig</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>so schnell wie möglich</translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation> Schritte/s</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Subject</source>
        <translation>Proband</translation>
    </message>
    <message>
        <source>Seed (start, goal)</source>
        <translation>Seed (Start, Ziel)</translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation>Zeitlimit</translation>
    </message>
    <message>
        <source>Step rate</source>
        <translation>Schrittrate</translation>
    </message>
    <message>
        <source>Navigator model</source>
        <translation>Navigator-Modell</translation>
    </message>
    <message>
        <source>Start New Run</source>
        <translation>Neuen Lauf starten</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>Los</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Give Up</source>
        <translation>Aufgeben</translation>
    </message>
    <message>
        <source>Data &gt;&gt;</source>
        <translation>Daten &gt;&gt;</translation>
    </message>
    <message>
        <source>Open in Workbench</source>
        <translation>In der Workbench öffnen</translation>
    </message>
    <message>
        <source>Signal per group</source>
        <translation>Signal je Gruppe</translation>
    </message>
    <message>
        <source>Experiment panel</source>
        <translation>Experimentbereich</translation>
    </message>
    <message>
        <source>The run so far</source>
        <translation>Der bisherige Lauf</translation>
    </message>
    <message>
        <source>Bug2 bumper (no model)</source>
        <translation>Bug2 mit Stoßfänger (kein Modell)</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Built-in &amp;Scenes</source>
        <translation>&amp;Eingebaute Szenen</translation>
    </message>
    <message>
        <source>Open Scene &amp;File...</source>
        <translation>Szenen&amp;datei öffnen...</translation>
    </message>
    <message>
        <source>Open Run in &amp;Workbench</source>
        <translation>Lauf in der &amp;Workbench öffnen</translation>
    </message>
    <message>
        <source>Save Run as &amp;CSV...</source>
        <translation>Lauf als &amp;CSV speichern...</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Schließen</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Lauf</translation>
    </message>
    <message>
        <source>Start &amp;New Run</source>
        <translation>&amp;Neuen Lauf starten</translation>
    </message>
    <message>
        <source>&amp;Go / Pause (P)</source>
        <translation>&amp;Los / Pause (P)</translation>
    </message>
    <message>
        <source>&amp;Step (N)</source>
        <translation>&amp;Schritt (N)</translation>
    </message>
    <message>
        <source>&amp;Give Up</source>
        <translation>&amp;Aufgeben</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene (M)</source>
        <translation>Roboter-Nahansicht / ganze Szene (M)</translation>
    </message>
    <message>
        <source>&amp;Data Panel</source>
        <translation>&amp;Datenbereich</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Briefing: Bug1 and Bug2</source>
        <translation>&amp;Einweisung: Bug1 und Bug2</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Tasten</translation>
    </message>
    <message>
        <source>Scene %1: press Start New Run</source>
        <translation>Szene %1: „Neuen Lauf starten“ drücken</translation>
    </message>
    <message>
        <source>Run %1 ready: drive with the arrow keys and W, A, S, D (Help &gt; Keys)</source>
        <translation>Lauf %1 bereit: mit den Pfeiltasten und W, A, S, D fahren (Hilfe &gt; Tasten)</translation>
    </message>
    <message>
        <source>(not stored)</source>
        <translation>(nicht gespeichert)</translation>
    </message>
    <message>
        <source>The scene stays hidden in experiment mode</source>
        <translation>Im Experimentmodus bleibt die Szene verborgen</translation>
    </message>
    <message>
        <source>v %1 units/s   ω %2 rad/s</source>
        <translation>v %1 Einheiten/s   ω %2 rad/s</translation>
    </message>
    <message>
        <source>Blocked: the last step was stopped</source>
        <translation>Blockiert: der letzte Schritt wurde gestoppt</translation>
    </message>
    <message>
        <source>Moving freely</source>
        <translation>Freie Fahrt</translation>
    </message>
    <message>
        <source>No step yet</source>
        <translation>Noch kein Schritt</translation>
    </message>
    <message>
        <source>No run yet.</source>
        <translation>Noch kein Lauf.</translation>
    </message>
    <message>
        <source>%1 mode, scene %2, step %3 (%4 s)</source>
        <translation>Modus %1, Szene %2, Schritt %3 (%4 s)</translation>
    </message>
    <message>
        <source>, %1 s left</source>
        <translation>, noch %1 s</translation>
    </message>
    <message>
        <source>
run %1, %2 steps stored</source>
        <translation>
Lauf %1, %2 Schritte gespeichert</translation>
    </message>
    <message>
        <source>
not stored (no database)</source>
        <translation>
nicht gespeichert (keine Datenbank)</translation>
    </message>
    <message>
        <source>
outcome: %1</source>
        <translation>
Ergebnis: %1</translation>
    </message>
    <message>
        <source>
paused: a drive key or Go starts the clock</source>
        <translation>
pausiert: eine Fahrtaste oder „Los“ startet die Uhr</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Data &lt;&lt;</source>
        <translation>Daten &lt;&lt;</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Scenes (*.json);;All files (*)</source>
        <translation>Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>No steps recorded yet.</source>
        <translation>Noch keine Schritte aufgezeichnet.</translation>
    </message>
    <message>
        <source>Save Run</source>
        <translation>Lauf speichern</translation>
    </message>
    <message>
        <source>Run files (*.csv)</source>
        <translation>Laufdateien (*.csv)</translation>
    </message>
    <message>
        <source>Briefing: Bug1 and Bug2</source>
        <translation>Einweisung: Bug1 und Bug2</translation>
    </message>
    <message>
        <source>&lt;p&gt;You drive the robot by touch: the close-up shows only the robot, which domes touch something, where it heads (blue) and where the goal lies (red), with the distance. Two classic strategies for a point robot that feels its way may help:&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug1&lt;/b&gt;&lt;br&gt;1. Head for the goal.&lt;br&gt;2. When you hit an obstacle, go all the way round it, keeping contact, and remember the point where you were closest to the goal.&lt;br&gt;3. Go back to that point, leave the obstacle there and head for the goal again.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug2&lt;/b&gt;&lt;br&gt;1. Head for the goal along the straight line from the start to the goal (the S-G line).&lt;br&gt;2. When an obstacle is in the way, follow its edge until you meet the S-G line again, closer to the goal than where you hit it.&lt;br&gt;3. Leave the obstacle there and go on along the line.&lt;/p&gt;&lt;p&gt;The robot is not a point: it is 140 long and 80 wide, it turns about its rear axle, and it loses contact easily when it follows an edge carelessly.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Sie steuern den Roboter nach Gefühl: Die Nahansicht zeigt nur den Roboter, welche Kuppeln etwas berühren, wohin er fährt (blau) und wo das Ziel liegt (rot), mit der Entfernung. Zwei klassische Strategien für einen punktförmigen Roboter, der sich vortastet, können helfen:&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug1&lt;/b&gt;&lt;br&gt;1. Auf das Ziel zufahren.&lt;br&gt;2. Bei einem Hindernis einmal ganz um es herumfahren, dabei den Kontakt halten, und sich den Punkt merken, an dem man dem Ziel am nächsten war.&lt;br&gt;3. Zu diesem Punkt zurückfahren, das Hindernis dort verlassen und wieder auf das Ziel zufahren.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug2&lt;/b&gt;&lt;br&gt;1. Auf der Geraden vom Start zum Ziel (der S-Z-Linie) auf das Ziel zufahren.&lt;br&gt;2. Steht ein Hindernis im Weg, seinem Rand folgen, bis man die S-Z-Linie wieder trifft, näher am Ziel als dort, wo man auf das Hindernis stieß.&lt;br&gt;3. Das Hindernis dort verlassen und auf der Linie weiterfahren.&lt;/p&gt;&lt;p&gt;Der Roboter ist kein Punkt: Er ist 140 lang und 80 breit, dreht sich um seine Hinterachse und verliert leicht den Kontakt, wenn er einem Rand unachtsam folgt.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Simulator Keys</source>
        <translation>Tasten des Simulators</translation>
    </message>
    <message>
        <source>Run %1 ready: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>Lauf %1 bereit: „Abspielen“ (P) lässt den Navigator fahren, „Schritt“ (N) macht einen Schritt</translation>
    </message>
    <message>
        <source>
paused: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>
pausiert: „Abspielen“ (P) lässt den Navigator fahren, „Schritt“ (N) macht einen Schritt</translation>
    </message>
    <message>
        <source>Plan drive (map of touches)</source>
        <translation>Planfahrt (Karte der Berührungen)</translation>
    </message>
    <message>
        <source>Thesis strategies (wall following)</source>
        <translation>Strategien der Arbeit (Wandfolgen)</translation>
    </message>
    <message>
        <source>How a navigator with a model drives: by a plan on a map of what it touched (the default, as tactile navigate), or by the thesis&apos;s strategies (tactile navigate --wall-follow). The Bug2 bumper baseline ignores it.</source>
        <translation>Wie ein Navigator mit Modell fährt: nach einem Plan auf einer Karte dessen, was er berührt hat (Standard, wie tactile navigate), oder nach den Strategien der Arbeit (tactile navigate --wall-follow). Die Bug2-Stoßfänger-Basislinie ignoriert dies.</translation>
    </message>
    <message>
        <source>Navigator drives by</source>
        <translation>Navigator fährt nach</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan are drawn (T: off)</source>
        <translation>Tastkarte und Plan des Navigators werden gezeigt (T: aus)</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan are hidden (T: on)</source>
        <translation>Tastkarte und Plan des Navigators sind ausgeblendet (T: ein)</translation>
    </message>
    <message>
        <source>Simulator truth (the ceiling, no model)</source>
        <translation>Wahrheit des Simulators (die Obergrenze, kein Modell)</translation>
    </message>
    <message>
        <source>0: the scene&apos;s own</source>
        <translation>0: die der Szene</translation>
    </message>
    <message>
        <source>Experiment mode: the seed of start and goal. Autonomous mode: the seed of the start, as in tactile navigate --seeds. 0: the scene&apos;s own start and goal (where the map benchmark starts).</source>
        <translation>Experimentmodus: der Seed für Start und Ziel. Autonomer Modus: der Seed des Starts, wie bei tactile navigate --seeds. 0: Start und Ziel der Szene selbst (wo der Karten-Benchmark startet).</translation>
    </message>
    <message>
        <source>Model %1 has no model for %2: the navigator reads those groups as no contact all run long.</source>
        <translation>Modell %1 hat kein Modell für %2: der Navigator liest diese Gruppen den ganzen Lauf lang als kein Kontakt.</translation>
    </message>
    <message>
        <source>Run %1 paused: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>Lauf %1 angehalten: Abspielen (P) lässt den Navigator fahren, Schritt (N) macht einen Schritt</translation>
    </message>
    <message>
        <source>Run %1: the navigator drives; Pause (P) stops it</source>
        <translation>Lauf %1: der Navigator fährt; Pause (P) hält ihn an</translation>
    </message>
    <message>
        <source>Run %1: driving, the clock runs; Give Up ends the run</source>
        <translation>Lauf %1: es wird gefahren, die Uhr läuft; Aufgeben beendet den Lauf</translation>
    </message>
    <message>
        <source>Goal reached: run %1 succeeded in %2 s</source>
        <translation>Ziel erreicht: Lauf %1 erfolgreich in %2 s</translation>
    </message>
</context>
<context>
    <name>tactile::gui::StatusPictureView</name>
    <message>
        <source>Choose a scene and a mode, then press Start.</source>
        <translation>Szene und Modus wählen, dann „Neuen Lauf starten“ drücken.</translation>
    </message>
    <message>
        <source>%1 units to the goal</source>
        <translation>%1 Einheiten bis zum Ziel</translation>
    </message>
    <message>
        <source>Whole scene (M: robot close-up)</source>
        <translation>Ganze Szene (M: Roboter-Nahansicht)</translation>
    </message>
    <message>
        <source>Robot close-up (M: whole scene)</source>
        <translation>Roboter-Nahansicht (M: ganze Szene)</translation>
    </message>
    <message>
        <source>Robot close-up (scene hidden)</source>
        <translation>Roboter-Nahansicht (Szene verborgen)</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>berührt</translation>
    </message>
    <message>
        <source>closed to the plan</source>
        <translation>für den Plan gesperrt</translation>
    </message>
    <message>
        <source>plan, odometry (T)</source>
        <translation>Plan, Odometrie (T)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::StepControlsView</name>
    <message>
        <source>Previous step (Left)</source>
        <translation>Vorheriger Schritt (Links)</translation>
    </message>
    <message>
        <source>Current step</source>
        <translation>Aktueller Schritt</translation>
    </message>
    <message>
        <source>Next step (Right)</source>
        <translation>Nächster Schritt (Rechts)</translation>
    </message>
    <message>
        <source>Scrub through the run</source>
        <translation>Durch den Lauf fahren</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Abspielen oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>Playing speed</source>
        <translation>Abspielgeschwindigkeit</translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation>%1 Schritte/s</translation>
    </message>
    <message>
        <source>of %1 steps</source>
        <translation>von %1 Schritten</translation>
    </message>
    <message>
        <source>Steps are numbered from 0 to %1</source>
        <translation>Die Schritte sind von 0 bis %1 nummeriert</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepCellsModel</name>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>fitted</source>
        <translation>angepasst</translation>
    </message>
    <message>
        <source>no model: %1</source>
        <translation>kein Modell: %1</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>Covariance</source>
        <translation>Kovarianz</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Ordnung</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>Untergrenze</translation>
    </message>
    <message>
        <source>Features</source>
        <translation>Merkmale</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Seed</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <source>Converged</source>
        <translation>Konvergiert</translation>
    </message>
    <message>
        <source>Accuracy %</source>
        <translation>Genauigkeit %</translation>
    </message>
    <message>
        <source>Balanced %</source>
        <translation>Balanciert %</translation>
    </message>
    <message>
        <source>Macro-F1</source>
        <translation>Makro-F1</translation>
    </message>
    <message>
        <source>Held-out loglik</source>
        <translation>Log-Likelihood (Testdaten)</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Fit ms</source>
        <translation>Anpassung ms</translation>
    </message>
    <message>
        <source>Predict ms</source>
        <translation>Vorhersage ms</translation>
    </message>
    <message>
        <source>%1: %2 test steps%3</source>
        <translation>%1: %2 Testschritte%3</translation>
    </message>
    <message>
        <source> (too few)</source>
        <translation> (zu wenige)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 (rarest %2, too few)</source>
        <translation>%1 (seltenste %2, zu wenige)</translation>
    </message>
    <message>
        <source>%1 (rarest %2)</source>
        <translation>%1 (seltenste %2)</translation>
    </message>
    <message>
        <source>Decision</source>
        <translation>Entscheidung</translation>
    </message>
    <message>
        <source>Test steps</source>
        <translation>Testschritte</translation>
    </message>
    <message>
        <source>no test data</source>
        <translation>keine Testdaten</translation>
    </message>
    <message>
        <source>%1 trees, depth %2, rate %3, weight %4</source>
        <translation>%1 Bäume, Tiefe %2, Rate %3, Gewicht %4</translation>
    </message>
    <message>
        <source>Trees</source>
        <translation>Bäume</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepPlot</name>
    <message>
        <source>Export PNG...</source>
        <translation>Als PNG exportieren...</translation>
    </message>
    <message>
        <source>Export PDF...</source>
        <translation>Als PDF exportieren...</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Als PNG exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>Als PDF exportieren</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Variance floor</source>
        <translation>Varianzuntergrenze</translation>
    </message>
    <message>
        <source>Model order</source>
        <translation>Modellordnung</translation>
    </message>
    <message>
        <source>Error: 100 - balanced accuracy (%)</source>
        <translation>Fehler: 100 − balancierte Genauigkeit (%)</translation>
    </message>
    <message>
        <source>group %1</source>
        <translation>Gruppe %1</translation>
    </message>
    <message>
        <source>Pareto front (%1)</source>
        <translation>Pareto-Front (%1)</translation>
    </message>
    <message>
        <source>No fitted cells yet.</source>
        <translation>Noch keine angepassten Zellen.</translation>
    </message>
    <message>
        <source>No fitted cells scored on test rows.</source>
        <translation>Keine angepasste Zelle wurde auf Testzeilen bewertet.</translation>
    </message>
    <message>
        <source>%1
%2: %3
%4: %5%6</source>
        <translation>%1
%2: %3
%4: %5%6</translation>
    </message>
    <message>
        <source>
cell %1 (click to select)</source>
        <translation>
Zelle %1 (zum Auswählen klicken)</translation>
    </message>
    <message>
        <source>Correct rate per class (%)</source>
        <translation>Trefferquote je Klasse (%)</translation>
    </message>
    <message>
        <source>Fit + predict time</source>
        <translation>Zeit für Anpassen + Vorhersagen</translation>
    </message>
    <message>
        <source>group %1, boosted trees</source>
        <translation>Gruppe %1, Boosted Trees</translation>
    </message>
    <message>
        <source>dots: Gaussian mixtures</source>
        <translation>Punkte: Gaußsche Mischmodelle</translation>
    </message>
    <message>
        <source>squares: boosted trees</source>
        <translation>Quadrate: Boosted Trees</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsView</name>
    <message>
        <source>No sweep</source>
        <translation>Kein Sweep</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>Alle Gruppen</translation>
    </message>
    <message>
        <source>Group:</source>
        <translation>Gruppe:</translation>
    </message>
    <message>
        <source>Confusion</source>
        <translation>Konfusionsmatrix</translation>
    </message>
    <message>
        <source>Class rates</source>
        <translation>Klassenraten</translation>
    </message>
    <message>
        <source>Rate vs floor</source>
        <translation>Rate vs. Untergrenze</translation>
    </message>
    <message>
        <source>Rate vs order</source>
        <translation>Rate vs. Ordnung</translation>
    </message>
    <message>
        <source>Time vs error</source>
        <translation>Zeit vs. Fehler</translation>
    </message>
    <message>
        <source>Contact patterns</source>
        <translation>Kontaktmuster</translation>
    </message>
    <message>
        <source>(cancelled: the finished cells)</source>
        <translation>(abgebrochen: die fertigen Zellen)</translation>
    </message>
    <message>
        <source>No cells yet.</source>
        <translation>Noch keine Zellen.</translation>
    </message>
    <message>
        <source>Select a cell.</source>
        <translation>Eine Zelle auswählen.</translation>
    </message>
    <message>
        <source>Cell %1: %2</source>
        <translation>Zelle %1: %2</translation>
    </message>
    <message>
        <source>Confusion (counts)</source>
        <translation>Konfusionsmatrix (Anzahl)</translation>
    </message>
    <message>
        <source>Confusion (row percent)</source>
        <translation>Konfusionsmatrix (Zeilenprozent)</translation>
    </message>
    <message>
        <source>No contact patterns were kept for this cell.</source>
        <translation>Für diese Zelle wurden keine Kontaktmuster aufbewahrt.</translation>
    </message>
    <message>
        <source>This cell was not scored: the test runs have no labelled rows of its group.</source>
        <translation>Diese Zelle wurde nicht bewertet: Die Testläufe haben keine gelabelten Zeilen ihrer Gruppe.</translation>
    </message>
    <message>
        <source>No cell is fitted yet.</source>
        <translation>Noch keine Zelle angepasst.</translation>
    </message>
    <message>
        <source>Precision per class, one-vs-rest, % - each group&apos;s best cell</source>
        <translation>Präzision je Klasse, One-vs-Rest, % – beste Zelle jeder Gruppe</translation>
    </message>
    <message>
        <source>This cell could not be fitted: %1</source>
        <translation>Diese Zelle konnte nicht angepasst werden: %1</translation>
    </message>
    <message>
        <source>Group %1, GMM %2, order %3, variance floor %4, %5 features, seed %6, %7 decision</source>
        <translation>Gruppe %1, GMM %2, Ordnung %3, Varianzuntergrenze %4, %5 Merkmale, Seed %6, Entscheidung %7</translation>
    </message>
    <message>
        <source>Group %1, %2, variance floor %3, %4 features, seed %5, %6 decision</source>
        <translation>Gruppe %1, %2, Varianzuntergrenze %3, %4 Merkmale, Seed %5, Entscheidung %6</translation>
    </message>
    <message>
        <source>step: the per-step argmax; online: the forward filter (causal); offline: forward-backward over the whole contact. Cells that differ only in it share one fit.</source>
        <translation>step: das Argmax je Schritt; online: der Vorwärtsfilter (kausal); offline: Vorwärts-Rückwärts über den ganzen Kontakt. Zellen, die sich nur darin unterscheiden, teilen sich eine Anpassung.</translation>
    </message>
    <message>
        <source>Decision:</source>
        <translation>Entscheidung:</translation>
    </message>
    <message>
        <source>All decisions</source>
        <translation>Alle Entscheidungen</translation>
    </message>
    <message>
        <source>Sweep %1: %2 cells stored, %3 fitted, %4 could not be fitted</source>
        <translation>Sweep %1: %2 Zellen gespeichert, %3 angepasst, %4 nicht anpassbar</translation>
    </message>
    <message>
        <source>no model of it is stored (Store Model of Cell stores one)</source>
        <translation>kein Modell daraus gespeichert (Modell der Zelle speichern speichert eines)</translation>
    </message>
    <message>
        <source>stored models of its cells: %1</source>
        <translation>gespeicherte Modelle seiner Zellen: %1</translation>
    </message>
    <message>
        <source>Precision per class, one-vs-rest (of the steps predicted a class, the share that are it), % - this cell</source>
        <translation>Präzision je Klasse, eine gegen die übrigen (von den als Klasse vorhergesagten Schritten der Anteil, der es ist), % - diese Zelle</translation>
    </message>
    <message>
        <source>Correct rate per class of this cell (of the steps of a class, the share predicted as it), %</source>
        <translation>Trefferquote je Klasse dieser Zelle (von den Schritten einer Klasse der als sie vorhergesagte Anteil), %</translation>
    </message>
    <message>
        <source>Group %1, boosted trees: %2 trees, depth %3, rate %4, min child weight %5, %6 features, seed %7, %8 decision</source>
        <translation>Gruppe %1, Boosted Trees: %2 Bäume, Tiefe %3, Rate %4, min. Blattgewicht %5, %6 Merkmale, Seed %7, Entscheidung %8</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsWindow</name>
    <message>
        <source>Sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <source>Export Report...</source>
        <translation>Bericht exportieren...</translation>
    </message>
    <message>
        <source>Store Model of Cell</source>
        <translation>Modell der Zelle speichern</translation>
    </message>
    <message>
        <source>Store Model</source>
        <translation>Modell speichern</translation>
    </message>
    <message>
        <source>Export Model of Cell...</source>
        <translation>Modell der Zelle exportieren...</translation>
    </message>
    <message>
        <source>Sweep %1: %2 (%3)</source>
        <translation>Sweep %1: %2 (%3)</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>HTML report (*.html);;Markdown report (*.md);;CSV tables (*.csv);;Text (*.txt)</source>
        <translation>HTML-Bericht (*.html);;Markdown-Bericht (*.md);;CSV-Tabellen (*.csv);;Text (*.txt)</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>Bericht nach %1 geschrieben</translation>
    </message>
    <message>
        <source>Select a cell first.</source>
        <translation>Zuerst eine Zelle auswählen.</translation>
    </message>
    <message>
        <source>That cell has no model: %1</source>
        <translation>Diese Zelle hat kein Modell: %1</translation>
    </message>
    <message>
        <source>Training the cell&apos;s model...</source>
        <translation>Das Modell der Zelle wird trainiert...</translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation>Modell exportieren</translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation>Modelldateien (*.json)</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>Model of Cell</source>
        <translation>Modell der Zelle</translation>
    </message>
    <message>
        <source>No model was stored: %1</source>
        <translation>Kein Modell gespeichert: %1</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored.</source>
        <translation>Modell „%1“ gespeichert.</translation>
    </message>
    <message>
        <source>Name (empty: %1):</source>
        <translation>Name (leer: %1):</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Close this window (%1)</source>
        <translation>Dieses Fenster schließen (%1)</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>Model written to %1 (not stored in the database).</source>
        <translation>Modell nach %1 geschrieben (nicht in der Datenbank gespeichert).</translation>
    </message>
    <message>
        <source>The sweep&apos;s status cannot be read: %1</source>
        <translation>Der Status des Sweeps lässt sich nicht lesen: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n Zelle</numerusform>
            <numerusform>%n Zellen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 cells done, %3 running, %4 pending, %5 failed</source>
        <translation>%1 von %2 Zellen fertig, %3 laufen, %4 ausstehend, %5 fehlgeschlagen</translation>
    </message>
    <message>
        <source>; about %1 left</source>
        <translation>; noch etwa %1</translation>
    </message>
    <message>
        <source>; waiting for workers (tactile sweep work)</source>
        <translation>; wartet auf Worker (tactile sweep work)</translation>
    </message>
    <message>
        <source>job %1 on %2: %3</source>
        <translation>Job %1 auf %2: %3</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TableView</name>
    <message>
        <source>Export CSV...</source>
        <translation>Als CSV exportieren...</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TimelineView</name>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>heading</source>
        <translation>Kurs</translation>
    </message>
    <message>
        <source>blocked</source>
        <translation>blockiert</translation>
    </message>
    <message>
        <source>%1 truth</source>
        <translation>%1 Ground Truth</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normalkraft</translation>
    </message>
    <message>
        <source>Shear</source>
        <translation>Scherkraft</translation>
    </message>
    <message>
        <source>Magnitude</source>
        <translation>Betrag</translation>
    </message>
    <message>
        <source>%1 model</source>
        <translation>%1 Modell</translation>
    </message>
    <message>
        <source>%1 ≠ label</source>
        <translation>%1 ≠ Label</translation>
    </message>
    <message>
        <source>holes</source>
        <translation>Lücken</translation>
    </message>
    <message>
        <source>step %1, %2 side: hole %3 units wide between domes %4 and %5</source>
        <translation>Schritt %1, Seite %2: Lücke von %3 Einheiten zwischen den Kuppeln %4 und %5</translation>
    </message>
    <message>
        <source>step %1, %2: the model says %3 (%4 %)</source>
        <translation>Schritt %1, %2: das Modell sagt %3 (%4 %)</translation>
    </message>
    <message>
        <source>, the label %1</source>
        <translation>, das Label %1</translation>
    </message>
    <message>
        <source>turn left</source>
        <translation>links drehen</translation>
    </message>
    <message>
        <source>turn right</source>
        <translation>rechts drehen</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>rückwärts</translation>
    </message>
    <message>
        <source>blue: facing +x
red: facing −x</source>
        <translation>blau: Richtung +x
rot: Richtung −x</translation>
    </message>
    <message>
        <source>red: command
grey: blocked</source>
        <translation>rot: Befehl
grau: blockiert</translation>
    </message>
    <message>
        <source>normal</source>
        <translation>Normalkraft</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>Scherkraft</translation>
    </message>
    <message>
        <source>magnitude</source>
        <translation>Betrag</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>steps %1-%2 (largest)</source>
        <translation>Schritte %1–%2 (größter Wert)</translation>
    </message>
    <message>
        <source>%1, sensor %2 (%3 %4): %5 %6</source>
        <translation>%1, Sensor %2 (%3 %4): %5 %6</translation>
    </message>
    <message>
        <source>step %1: heading %2° (%3)</source>
        <translation>Schritt %1: Kurs %2° (%3)</translation>
    </message>
    <message>
        <source>blue: facing +x</source>
        <translation>blau: Richtung +x</translation>
    </message>
    <message>
        <source>red: facing −x</source>
        <translation>rot: Richtung −x</translation>
    </message>
    <message>
        <source>step %1: v %2, omega %3%4</source>
        <translation>Schritt %1: v %2, omega %3%4</translation>
    </message>
    <message>
        <source>, blocked</source>
        <translation>, blockiert</translation>
    </message>
    <message>
        <source>%1 online</source>
        <translation>%1 online</translation>
    </message>
    <message>
        <source>%1 offline</source>
        <translation>%1 offline</translation>
    </message>
    <message>
        <source>step %1, %2: the %3 decision is %4</source>
        <translation>Schritt %1, %2: Entscheidung %3: %4</translation>
    </message>
    <message>
        <source>online (causal)</source>
        <translation>online (kausal)</translation>
    </message>
    <message>
        <source>offline (whole contact)</source>
        <translation>offline (ganzer Kontakt)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TrainingDialog</name>
    <message>
        <source>Train and sweep</source>
        <translation>Trainieren und Sweep</translation>
    </message>
    <message>
        <source>Label set:</source>
        <translation>Labelsatz:</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Train</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Test</translation>
    </message>
    <message>
        <source>Runs:</source>
        <translation>Läufe:</translation>
    </message>
    <message>
        <source>Split:</source>
        <translation>Aufteilung:</translation>
    </message>
    <message>
        <source>Groups:</source>
        <translation>Gruppen:</translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation>Gauß</translation>
    </message>
    <message>
        <source>GMM</source>
        <translation>GMM</translation>
    </message>
    <message>
        <source>Methods:</source>
        <translation>Verfahren:</translation>
    </message>
    <message>
        <source>Model orders (components per class), comma-separated</source>
        <translation>Modellordnungen (Komponenten je Klasse), durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Orders:</source>
        <translation>Ordnungen:</translation>
    </message>
    <message>
        <source>Covariance:</source>
        <translation>Kovarianz:</translation>
    </message>
    <message>
        <source>Variance floors, comma-separated</source>
        <translation>Varianzuntergrenzen, durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Variance floors:</source>
        <translation>Varianzuntergrenzen:</translation>
    </message>
    <message>
        <source>Features:</source>
        <translation>Merkmale:</translation>
    </message>
    <message>
        <source>Seeds:</source>
        <translation>Seeds:</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>all cores</source>
        <translation>alle Kerne</translation>
    </message>
    <message>
        <source>Threads:</source>
        <translation>Threads:</translation>
    </message>
    <message>
        <source>Run sweep</source>
        <translation>Sweep starten</translation>
    </message>
    <message>
        <source>Train model</source>
        <translation>Modell trainieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Choose the runs and the grid, then run a sweep or train a model.</source>
        <translation>Läufe und Raster wählen, dann einen Sweep starten oder ein Modell trainieren.</translation>
    </message>
    <message>
        <source>Orders</source>
        <translation>Ordnungen</translation>
    </message>
    <message>
        <source>Variance floors</source>
        <translation>Varianzuntergrenzen</translation>
    </message>
    <message>
        <source>Seeds</source>
        <translation>Seeds</translation>
    </message>
    <message numerus="yes">
        <source>Sweep of %n cell(s) started.</source>
        <translation>
            <numerusform>Sweep mit %n Zelle gestartet.</numerusform>
            <numerusform>Sweep mit %n Zellen gestartet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Training started.</source>
        <translation>Training gestartet.</translation>
    </message>
    <message>
        <source>Cancelling: running fits stop after their current iteration...</source>
        <translation>Abbruch: Laufende Anpassungen enden nach ihrer aktuellen Iteration...</translation>
    </message>
    <message>
        <source>%1 of %2 done, about %3 left</source>
        <translation>%1 von %2 fertig, noch etwa %3</translation>
    </message>
    <message>
        <source>%1 of %2 done</source>
        <translation>%1 von %2 fertig</translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation>Der Sweep ist fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 cancelled after %2 s; its %n finished cell(s) are stored.</source>
        <translation>
            <numerusform>Sweep %1 nach %2 s abgebrochen; seine %n fertige Zelle ist gespeichert.</numerusform>
            <numerusform>Sweep %1 nach %2 s abgebrochen; seine %n fertigen Zellen sind gespeichert.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 finished: %n cell(s) in %2 s.</source>
        <translation>
            <numerusform>Sweep %1 fertig: %n Zelle in %2 s.</numerusform>
            <numerusform>Sweep %1 fertig: %n Zellen in %2 s.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: skipped (%2)</source>
        <translation>%1: übersprungen (%2)</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored (%2 s). %3</source>
        <translation>Modell „%1“ gespeichert (%2 s). %3</translation>
    </message>
    <message>
        <source>Training cancelled; nothing was stored.</source>
        <translation>Training abgebrochen; nichts wurde gespeichert.</translation>
    </message>
    <message>
        <source>Training failed: %1</source>
        <translation>Training fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>each group&apos;s default settings</source>
        <translation>Standardeinstellungen jeder Gruppe</translation>
    </message>
    <message>
        <source>Train model with:</source>
        <translation>Modell trainieren mit:</translation>
    </message>
    <message>
        <source>Train one model per group and store it in the database</source>
        <translation>Ein Modell je Gruppe trainieren und in der Datenbank speichern</translation>
    </message>
    <message>
        <source>Plan:</source>
        <translation>Plan:</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>Balanced accuracy %</source>
        <translation>Balancierte Genauigkeit %</translation>
    </message>
    <message>
        <source>Accuracy %</source>
        <translation>Genauigkeit %</translation>
    </message>
    <message>
        <source>Training samples</source>
        <translation>Trainingsbeispiele</translation>
    </message>
    <message>
        <source>Test samples</source>
        <translation>Testbeispiele</translation>
    </message>
    <message>
        <source>Fit s</source>
        <translation>Anpassung s</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n Zelle</numerusform>
            <numerusform>%n Zellen</numerusform>
        </translation>
    </message>
    <message>
        <source>; the time left shows once the first cells finish (no sweep is stored yet to estimate from)</source>
        <translation>; die Restzeit erscheint, sobald die ersten Zellen fertig sind (noch kein gespeicherter Sweep, aus dem sie sich schätzen ließe)</translation>
    </message>
    <message>
        <source>Ready.</source>
        <translation>Bereit.</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>übersprungen: %1</translation>
    </message>
    <message>
        <source>Decision modes: step = each step alone; online = HMM forward filter over the contact (causal, what a navigator may use); offline = forward-backward over the whole contact. A sweep scores every ticked mode (cells differing only here share one fit); Train model always scores all three and its models decide online by default</source>
        <translation>Entscheidungsmodi: step = jeder Schritt für sich; online = HMM-Vorwärtsfilter über den Kontakt (kausal, was ein Navigator nutzen darf); offline = Vorwärts-Rückwärts über den ganzen Kontakt. Ein Sweep bewertet jeden angehakten Modus (Zellen, die sich nur hierin unterscheiden, teilen eine Anpassung); „Modell trainieren“ bewertet immer alle drei, und seine Modelle entscheiden standardmäßig online</translation>
    </message>
    <message>
        <source>Decisions:</source>
        <translation>Entscheidungen:</translation>
    </message>
    <message>
        <source>%1 scored 0 on %2 test steps</source>
        <translation>%1 erzielte 0 auf %2 Testschritten</translation>
    </message>
    <message>
        <source>%1 had no test data</source>
        <translation>%1 hatte keine Testdaten</translation>
    </message>
    <message>
        <source>%1. Store the model anyway?</source>
        <translation>%1. Das Modell trotzdem speichern?</translation>
    </message>
    <message>
        <source>Store the model?</source>
        <translation>Modell speichern?</translation>
    </message>
    <message>
        <source>The model was not stored (%1).</source>
        <translation>Das Modell wurde nicht gespeichert (%1).</translation>
    </message>
    <message>
        <source>%1: balanced accuracy %2 % (%3 test steps)</source>
        <translation>%1: balancierte Genauigkeit %2 % (%3 Testschritte)</translation>
    </message>
    <message>
        <source>%1: no test data</source>
        <translation>%1: keine Testdaten</translation>
    </message>
    <message>
        <source>no test data</source>
        <translation>keine Testdaten</translation>
    </message>
    <message>
        <source>score on the test runs</source>
        <translation>auf den Testläufen bewerten</translation>
    </message>
    <message>
        <source>leave one scene out: each scene scored by models trained without it</source>
        <translation>je eine Szene auslassen: jede Szene mit Modellen bewertet, die ohne sie trainiert wurden</translation>
    </message>
    <message>
        <source>leave one run out (Train model only; a sweep cannot)</source>
        <translation>je einen Lauf auslassen (nur „Modell trainieren“; ein Sweep kann es nicht)</translation>
    </message>
    <message>
        <source>by-run: the runs marked Test are scored (the command line&apos;s default); by-scene: each scene&apos;s runs (marked for training) are scored by models trained without that scene, no test runs; leave-one-run-out: each run scored by a model trained on the others (Train model only)</source>
        <translation>by-run: die als Test markierten Läufe werden bewertet (Vorgabe der Kommandozeile); by-scene: die (zum Training markierten) Läufe jeder Szene werden mit Modellen bewertet, die ohne diese Szene trainiert wurden, keine Testläufe; leave-one-run-out: jeder Lauf mit einem auf den anderen trainierten Modell bewertet (nur „Modell trainieren“)</translation>
    </message>
    <message>
        <source>each group&apos;s default</source>
        <translation>Standard jeder Gruppe</translation>
    </message>
    <message>
        <source>Evidence weight:</source>
        <translation>Evidenzgewicht:</translation>
    </message>
    <message>
        <source>Leave Them Out</source>
        <translation>Weglassen</translation>
    </message>
    <message>
        <source>Untick the groups the test runs cannot score</source>
        <translation>Die Gruppen abwählen, die die Testläufe nicht bewerten können</translation>
    </message>
    <message numerus="yes">
        <source>, about %1 on %n thread(s) (each cell&apos;s rows, order and covariance form, timed by %2 stored cells)</source>
        <translation>
            <numerusform>, etwa %1 auf %n Thread (Zeilen, Ordnung und Kovarianzform jeder Zelle, gemessen an %2 gespeicherten Zellen)</numerusform>
            <numerusform>, etwa %1 auf %n Threads (Zeilen, Ordnung und Kovarianzform jeder Zelle, gemessen an %2 gespeicherten Zellen)</numerusform>
        </translation>
    </message>
    <message>
        <source>the test runs hold no labelled contact steps of %1</source>
        <translation>die Testläufe enthalten keine beschrifteten Kontaktschritte von %1</translation>
    </message>
    <message>
        <source>too few (under %1) of %2</source>
        <translation>zu wenige (unter %1) von %2</translation>
    </message>
    <message>
        <source>Cannot be scored: %1. Their cells would be fitted but read &quot;no test data&quot;.</source>
        <translation>Nicht bewertbar: %1. Ihre Zellen würden angepasst, zeigten aber „keine Testdaten“.</translation>
    </message>
    <message>
        <source>Plan for workers</source>
        <translation>Für Worker planen</translation>
    </message>
    <message>
        <source>Store the sweep with every cell pending, to be filled by tactile sweep work processes on any machine that reaches the database, or by a Slurm job array</source>
        <translation>Den Sweep mit allen Zellen ausstehend speichern, damit tactile-sweep-work-Prozesse auf jedem Rechner, der die Datenbank erreicht, oder ein Slurm-Job-Array ihn füllen</translation>
    </message>
    <message>
        <source>Copy Commands</source>
        <translation>Befehle kopieren</translation>
    </message>
    <message>
        <source>The sweep was not planned: %1</source>
        <translation>Der Sweep wurde nicht geplant: %1</translation>
    </message>
    <message>
        <source># One worker; start as many as you like, on any machine that reaches the database:</source>
        <translation># Ein Worker; starten Sie beliebig viele, auf jedem Rechner, der die Datenbank erreicht:</translation>
    </message>
    <message>
        <source># Or 4 workers as a Slurm job array:</source>
        <translation># Oder 4 Worker als Slurm-Job-Array:</translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 planned: %n cell(s), all pending, for the workers below.</source>
        <translation>
            <numerusform>Sweep %1 geplant: %n Zelle, ausstehend, für die Worker unten.</numerusform>
            <numerusform>Sweep %1 geplant: %n Zellen, alle ausstehend, für die Worker unten.</numerusform>
        </translation>
    </message>
    <message>
        <source>Boosted trees</source>
        <translation>Boosted Trees</translation>
    </message>
    <message>
        <source>Gradient-boosted trees (XGBoost) under the same class chain: the online and offline decisions use their class posteriors divided by the priors</source>
        <translation>Gradient-Boosted Trees (XGBoost) unter derselben Klassenkette: die Online- und Offline-Entscheidungen verwenden ihre A-posteriori-Wahrscheinlichkeiten geteilt durch die Prioren</translation>
    </message>
    <message>
        <source>Boosting rounds (trees per class), comma-separated</source>
        <translation>Boosting-Runden (Bäume je Klasse), durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Largest tree depths, comma-separated</source>
        <translation>Größte Baumtiefen, durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Learning rates (shrinkage of each round), comma-separated</source>
        <translation>Lernraten (Schrumpfung jeder Runde), durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Least summed weight in a leaf, comma-separated</source>
        <translation>Kleinstes summiertes Gewicht in einem Blatt, durch Kommas getrennt</translation>
    </message>
    <message>
        <source>rounds</source>
        <translation>Runden</translation>
    </message>
    <message>
        <source>depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <source>min weight</source>
        <translation>Min.-Gewicht</translation>
    </message>
    <message>
        <source>Trees:</source>
        <translation>Bäume:</translation>
    </message>
    <message>
        <source>Trees</source>
        <translation>Bäume</translation>
    </message>
    <message>
        <source>Depths</source>
        <translation>Tiefen</translation>
    </message>
    <message>
        <source>Learning rates</source>
        <translation>Lernraten</translation>
    </message>
    <message>
        <source>Min child weights</source>
        <translation>Min. Blattgewichte</translation>
    </message>
    <message>
        <source>Train model uses each group&apos;s default family with its settings (order, covariance and floor, or rounds and depth), features and evidence weight, as tactile train does; unticked, the first value of every list above</source>
        <translation>„Modell trainieren“ nimmt wie tactile train die Standardfamilie jeder Gruppe mit ihren Einstellungen (Ordnung, Kovarianz und Untergrenze oder Runden und Tiefe), Merkmale und Evidenzgewicht; ohne Haken den ersten Wert jeder Liste oben</translation>
    </message>
    <message>
        <source>Train model: the weight of each step&apos;s evidence in the online and offline decisions (1 is the plain HMM; smaller lets the class chain outweigh single steps, larger lets a few steps outweigh the chain), as tactile train --emission-weight. Sweeps always use each group&apos;s default for the method</source>
        <translation>Modell trainieren: das Gewicht der Evidenz jedes Schritts in den Online- und Offline-Entscheidungen (1 ist das einfache HMM; kleiner lässt die Klassenkette einzelne Schritte überwiegen, größer lässt wenige Schritte die Kette überwiegen), wie tactile train --emission-weight. Sweeps verwenden immer den Standard jeder Gruppe für die Methode</translation>
    </message>
</context>
<context>
    <name>tactile::gui::UserGuideWindow</name>
    <message>
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>User Guide: %1</source>
        <translation>Benutzerhandbuch: %1</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Inhalt</translation>
    </message>
    <message>
        <source>%1 is not part of the embedded guide; it is in the source tree.</source>
        <translation>%1 gehört nicht zum eingebetteten Handbuch; es liegt im Quellbaum.</translation>
    </message>
</context>
</TS>
