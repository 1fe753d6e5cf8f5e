<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ContactClass</name>
    <message>
        <source>No contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leaving wall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead path</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SimKeys</name>
    <message>
        <source>Faster forward by a large step (+20 units/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slower (or backward) by a large step (-20 units/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faster forward by a small step (+5 units/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slower (or backward) by a small step (-5 units/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn left by a large step (+0.2 rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn right by a large step (-0.2 rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn left by a small step (+0.05 rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn right by a small step (-0.05 rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (v = 0, omega = 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot close-up / whole scene (close-up only in experiment mode)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause / go on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One step (while paused)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tactile Workbench: tactile-navigation research desktop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the run database DB (default: the last one used).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the run named NAME.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put the cursor on step K.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--step needs a step number, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--run needs --db</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no such database</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Render the window (or with --sweep the results window) at 1600x1000 to the PNG file FILE, then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the results of the stored sweep ID (needs --db).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the stored model NAME&apos;s predictions under the labels (needs --run).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--sweep needs --db</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--model needs --run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--sweep needs a sweep id, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the simulator window on SCENE (a built-in scene, a scene JSON file or random:N:SEED); runs go into --db (or the last database).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: the subject&apos;s name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate --mode experiment: the seed of start and goal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: start a run and replay the v, omega commands of the run file FILE, one a step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: steps per second (default 10; 0 as fast as possible).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: show the data panel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: show the whole scene where allowed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--seed needs a positive number, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--rate needs a number &gt;= 0, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --simulate: practice (default), experiment or autonomous.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no stored model named &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--mode must be practice, experiment or autonomous, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::ExperimentPanel</name>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Strategies</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelModel</name>
    <message>
        <source>Label steps %1-%2 as %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move %1 segment to steps %2-%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete segment</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelPanelView</name>
    <message>
        <source>Label set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The label set being edited; choose another to open it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Selected group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checked groups</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Groups in contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label the %1 group (with &quot;Checked groups&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classes (keys 1-5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label the selected steps as %1 (key %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At the cursor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete segment (Del)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Selection:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Agree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kappa</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Labels against the run&apos;s truth, over the labelled steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Agreement with truth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create or open a label set first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No group to label: check a group or change the mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Labelled steps %1-%2 as %3 in %n group(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>No segment of the selected group under the cursor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no label set)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New label set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No label set is open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save label set as</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name of the copy:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label files (*.csv *.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Export labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV (*.csv);;JSON (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>steps %1-%2 (%n step(s))</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>none (an edit labels the current step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unlabelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2, steps %3-%4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::MainWindow</name>
    <message>
        <source>Runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open Database...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New Database...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Runs...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;Labels...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Segment Start Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+Shift+Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Segment Start Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+Shift+Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Segment End Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Segment End Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear Selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Previous Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward 10 Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back 10 Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward 100 Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back 100 Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward One Screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back One Screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play / Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour Route by Label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heatmap: Normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heatmap: Shear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heatmap: Magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom to Whole Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Tactile Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open or create a database before importing runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Importing %n run file(s)...</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Imported %n run(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>; cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>; %n file(s) not imported: </source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>New database</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tactile databases (*.db);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open database</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tactile databases (*.db *.sqlite);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run files (*.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tactile Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  |  selected %1-%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No run open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No database open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label set: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No label set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Tactile Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tactile Workbench %1
Research workbench for tactile-based mobile-robot navigation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Learn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Train and Sweep...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+T</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Sweep Results...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export Model...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Model...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A sweep or training is running. Cancel it and quit? Finished sweep cells stay stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a database first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database has no sweep yet: Learn &gt; Train and Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (%3 cells, %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Sweep Results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database has no model yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; written to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store as:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Predictions: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Predictions shown: %n step(s) disagree with the labels (N: next)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Show &amp;Predictions...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Hide Predictions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Next Disagreement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pre&amp;vious Disagreement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a run first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database has no model yet: Learn &gt; Train and Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No predictions shown: Learn &gt; Show Predictions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model agrees with the labels everywhere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step %1, group %2: the model says %3 (%4 %), the label %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Navigator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Simulation...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+N</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::ModelPickerDialog</name>
    <message>
        <source>Show Predictions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A model per group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The timeline shows each group&apos;s predicted class under its labels, pale where the model is unsure, and marks where it disagrees with the labels (N: next disagreement).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorPanelView</name>
    <message>
        <source>This run has no navigator columns. Runs written by &apos;tactile navigate&apos; have them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command set:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current control mode:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status-%1:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorStripView</name>
    <message>
        <source>strategy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::RouteView</name>
    <message>
        <source>%1 units to the goal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No run open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whole scene (M: close-up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close-up (M: whole scene)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole %1 wide</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListModel</name>
    <message>
        <source>%1
imported from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subject</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Labelled</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListView</name>
    <message>
        <source>Filter runs by name, scene, subject or outcome</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimSession</name>
    <message>
        <source>An experiment run needs the subject&apos;s name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A subject&apos;s name must be one line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autonomous mode needs a driver.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The step length must be in (0, 1] seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The time limit must be positive.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimWindow</name>
    <message>
        <source>Run %1 ended: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tactile Simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Practice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autonomous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needed in experiment mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subject</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed (start, goal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Navigator model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start New Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data &gt;&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open in Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal per group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Experiment panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run so far</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bug2 bumper (no model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built-in &amp;Scenes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Scene &amp;File...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Run in &amp;Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Run as &amp;CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start &amp;New Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Go / Pause (P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Step (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Give Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene (M)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Data Panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Briefing: Bug1 and Bug2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene %1: press Start New Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1 ready: drive with the arrow keys and W, A, S, D (Help &gt; Keys)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not stored)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The scene stays hidden in experiment mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>v %1 units/s   ω %2 rad/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Blocked: the last step was stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving freely</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No step yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No run yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mode, scene %2, step %3 (%4 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 s left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
run %1, %2 steps stored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
not stored (no database)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
outcome: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
paused: a drive key or Go starts the clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data &lt;&lt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenes (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No steps recorded yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Briefing: Bug1 and Bug2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;You drive the robot by touch: the close-up shows only the robot, which domes touch something, where it heads (blue) and where the goal lies (red), with the distance. Two classic strategies for a point robot that feels its way may help:&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug1&lt;/b&gt;&lt;br&gt;1. Head for the goal.&lt;br&gt;2. When you hit an obstacle, go all the way round it, keeping contact, and remember the point where you were closest to the goal.&lt;br&gt;3. Go back to that point, leave the obstacle there and head for the goal again.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug2&lt;/b&gt;&lt;br&gt;1. Head for the goal along the straight line from the start to the goal (the S-G line).&lt;br&gt;2. When an obstacle is in the way, follow its edge until you meet the S-G line again, closer to the goal than where you hit it.&lt;br&gt;3. Leave the obstacle there and go on along the line.&lt;/p&gt;&lt;p&gt;The robot is not a point: it is 140 long and 80 wide, it turns about its rear axle, and it loses contact easily when it follows an edge carelessly.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator Keys</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::StatusPictureView</name>
    <message>
        <source>Choose a scene and a mode, then press Start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 units to the goal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whole scene (M: robot close-up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot close-up (M: whole scene)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot close-up (scene hidden)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::StepControlsView</name>
    <message>
        <source>Previous step (Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next step (Right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scrub through the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Playing speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepCellsModel</name>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Covariance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Floor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Features</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Converged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accuracy %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Balanced %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Macro-F1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Held-out loglik</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Predict ms</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepPlot</name>
    <message>
        <source>Export PNG...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PDF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variance floor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correct rate per class (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit + predict time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error: 100 - balanced accuracy (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>group %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pareto front (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No cells with a model yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No cells with a model scored on test rows.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsView</name>
    <message>
        <source>No sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All groups</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confusion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Class rates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate vs floor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate vs order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time vs error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact patterns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep %1: %2 cells, %3 with a model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(cancelled: the finished cells)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No cell has a model yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No cells yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a cell.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cell %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This cell has no model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confusion (counts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confusion (row percent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Per-class correct rate of this cell (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No contact patterns were kept for this cell.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>each group&apos;s best cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This cell was not scored: the test runs have no labelled rows of its group.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group %1, GMM %2, order %3, variance floor %4, %5 features, seed %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group %1, %2, variance floor %3, %4 features, seed %5</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsWindow</name>
    <message>
        <source>Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Report...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store Model of Cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name (empty: automatic):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Model of Cell...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep %1: %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HTML report (*.html);;Markdown report (*.md);;CSV tables (*.csv);;Text (*.txt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a cell first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>That cell has no model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training the cell&apos;s model...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model of Cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No model was stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::TableView</name>
    <message>
        <source>Export CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::TimelineView</name>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>heading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>L</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>blocked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 truth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ≠ label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1, %2 side: hole %3 units wide between domes %4 and %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1, %2: the model says %3 (%4 %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, the label %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactile::gui::TrainingDialog</name>
    <message>
        <source>Train and sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label set:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Score on the test runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leave one run out (training only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Split:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Groups:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GMM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Methods:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model orders (components per class), comma-separated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Orders:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Covariance:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variance floors, comma-separated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variance floors:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Features:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seeds:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all cores</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Threads:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the runs and the grid, then run a sweep or train a model.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Orders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variance floors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Sweep of %n cell(s) started.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Training started.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelling: running fits stop after their current iteration...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 done, about %3 left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 cancelled after %2 s; its %n finished cell(s) are stored.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 finished: %n cell(s) in %2 s.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1: balanced accuracy %2 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: skipped (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored (%2 s). %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training cancelled; nothing was stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>each group&apos;s default settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train model uses each group&apos;s default order, covariance, floor and features, as tactile train does; unticked, the first value of every list above</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train model with:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train one model per group and store it in the database</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
