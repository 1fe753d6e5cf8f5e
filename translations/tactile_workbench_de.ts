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
        <source>Render the window at 1600x1000 to the PNG file FILE, then quit.</source>
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
</context>
</TS>
