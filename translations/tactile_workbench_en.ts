<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>tactile::gui::LabelPanelView</name>
    <message numerus="yes">
        <source>Imported %n segment(s)</source>
        <translation>
            <numerusform>Imported %n segment</numerusform>
            <numerusform>Imported %n segments</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>steps %1-%2 (%n step(s))</source>
        <translation>
            <numerusform>steps %1-%2 (%n step)</numerusform>
            <numerusform>steps %1-%2 (%n steps)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Undefined: both sides use one and the same class on all %n step(s), so chance agreement is 100 %</source>
        <translation>
            <numerusform>Undefined: both sides use one and the same class on the %n step, so chance agreement is 100 %</numerusform>
            <numerusform>Undefined: both sides use one and the same class on all %n steps, so chance agreement is 100 %</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactile::gui::MainWindow</name>
    <message numerus="yes">
        <source>Predictions shown: %n step(s) disagree with the labels (N: next)</source>
        <translation>
            <numerusform>Predictions shown: %n step disagrees with the labels (N: next)</numerusform>
            <numerusform>Predictions shown: %n steps disagree with the labels (N: next)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Importing %n run file(s)...</source>
        <translation>
            <numerusform>Importing %n run file...</numerusform>
            <numerusform>Importing %n run files...</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n run(s)</source>
        <translation>
            <numerusform>Imported %n run</numerusform>
            <numerusform>Imported %n runs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n file(s) not imported: </source>
        <translation>
            <numerusform>; %n file not imported: </numerusform>
            <numerusform>; %n files not imported: </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Drop one database at a time (%n dropped).</source>
        <translation>
            <numerusform>Drop one database at a time (%n dropped).</numerusform>
            <numerusform>Drop one database at a time (%n dropped).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Run written to %1 (%n step(s))</source>
        <translation>
            <numerusform>Run written to %1 (%n step)</numerusform>
            <numerusform>Run written to %1 (%n steps)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported run &apos;%1&apos; (%n step(s))</source>
        <translation>
            <numerusform>Imported run &apos;%1&apos; (%n step)</numerusform>
            <numerusform>Imported run &apos;%1&apos; (%n steps)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsWindow</name>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n cell</numerusform>
            <numerusform>%n cells</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactile::gui::TrainingDialog</name>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n cell</numerusform>
            <numerusform>%n cells</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, about %1 on %n thread(s) (each cell&apos;s rows, order and covariance form, timed by %2 stored cells)</source>
        <translation>
            <numerusform>, about %1 on %n thread (each cell&apos;s rows, order and covariance form, timed by %2 stored cells)</numerusform>
            <numerusform>, about %1 on %n threads (each cell&apos;s rows, order and covariance form, timed by %2 stored cells)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep of %n cell(s) started.</source>
        <translation>
            <numerusform>Sweep of %n cell started.</numerusform>
            <numerusform>Sweep of %n cells started.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 cancelled after %2 s; its %n finished cell(s) are stored.</source>
        <translation>
            <numerusform>Sweep %1 cancelled after %2 s; its %n finished cell are stored.</numerusform>
            <numerusform>Sweep %1 cancelled after %2 s; its %n finished cells are stored.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 finished: %n cell(s) in %2 s.</source>
        <translation>
            <numerusform>Sweep %1 finished: %n cell in %2 s.</numerusform>
            <numerusform>Sweep %1 finished: %n cells in %2 s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 planned: %n cell(s), all pending, for the workers below.</source>
        <translation>
            <numerusform>Sweep %1 planned: %n cell, all pending, for the workers below.</numerusform>
            <numerusform>Sweep %1 planned: %n cells, all pending, for the workers below.</numerusform>
        </translation>
    </message>
</context>
</TS>
