<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>ContactClass</name>
    <message>
        <source>No contact</source>
        <translation>无接触</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>墙</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>墙角</translation>
    </message>
    <message>
        <source>Leaving wall</source>
        <translation>离开墙</translation>
    </message>
    <message>
        <source>Dead path</source>
        <translation>死路</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(无)</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 毫秒</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
</context>
<context>
    <name>Shortcuts</name>
    <message>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>编辑</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>转到</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>学习</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>帮助</translation>
    </message>
    <message>
        <source>Open a database</source>
        <translation>打开数据库</translation>
    </message>
    <message>
        <source>Import run files</source>
        <translation>导入运行文件</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>退出</translation>
    </message>
    <message>
        <source>Undo the last label edit</source>
        <translation>撤销上一次标签编辑</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Label as %1</source>
        <translation>标注为%1</translation>
    </message>
    <message>
        <source>Delete the segments under the cursor</source>
        <translation>删除光标处的片段</translation>
    </message>
    <message>
        <source>Move the segment&apos;s start one step left</source>
        <translation>将片段起点左移一步</translation>
    </message>
    <message>
        <source>Move the segment&apos;s start one step right</source>
        <translation>将片段起点右移一步</translation>
    </message>
    <message>
        <source>Move the segment&apos;s end one step left</source>
        <translation>将片段终点左移一步</translation>
    </message>
    <message>
        <source>Move the segment&apos;s end one step right</source>
        <translation>将片段终点右移一步</translation>
    </message>
    <message>
        <source>Clear the selection (in a text field: leave the field)</source>
        <translation>清除选区（在文本框中：离开文本框）</translation>
    </message>
    <message>
        <source>Next step</source>
        <translation>下一步</translation>
    </message>
    <message>
        <source>Previous step</source>
        <translation>上一步</translation>
    </message>
    <message>
        <source>Forward 10 steps</source>
        <translation>前进 10 步</translation>
    </message>
    <message>
        <source>Back 10 steps</source>
        <translation>后退 10 步</translation>
    </message>
    <message>
        <source>Forward 100 steps</source>
        <translation>前进 100 步</translation>
    </message>
    <message>
        <source>Back 100 steps</source>
        <translation>后退 100 步</translation>
    </message>
    <message>
        <source>Forward one screen</source>
        <translation>前进一屏</translation>
    </message>
    <message>
        <source>Back one screen</source>
        <translation>后退一屏</translation>
    </message>
    <message>
        <source>First step</source>
        <translation>第一步</translation>
    </message>
    <message>
        <source>Last step</source>
        <translation>最后一步</translation>
    </message>
    <message>
        <source>Play or pause</source>
        <translation>播放或暂停</translation>
    </message>
    <message>
        <source>Route: robot close-up or whole scene</source>
        <translation>路线：机器人特写或整个场景</translation>
    </message>
    <message>
        <source>Zoom the timelines out to the whole run</source>
        <translation>将时间轴缩放至整个运行</translation>
    </message>
    <message>
        <source>Train and sweep</source>
        <translation>训练与扫描</translation>
    </message>
    <message>
        <source>Show a model&apos;s predictions</source>
        <translation>显示模型的预测</translation>
    </message>
    <message>
        <source>Next stretch where the model disagrees with the labels</source>
        <translation>下一处模型与标签不一致的区段</translation>
    </message>
    <message>
        <source>Previous stretch where the model disagrees with the labels</source>
        <translation>上一处模型与标签不一致的区段</translation>
    </message>
    <message>
        <source>This list of keyboard shortcuts</source>
        <translation>本快捷键列表</translation>
    </message>
    <message>
        <source>New simulation window</source>
        <translation>新建模拟器窗口</translation>
    </message>
    <message>
        <source>Label the selection (or the visible steps) from the predictions&apos; model</source>
        <translation>用预测所用模型标注所选（或可见）的步</translation>
    </message>
    <message>
        <source>Next stretch where the model is unsure (below the threshold in Preferences)</source>
        <translation>下一段模型不确定的区间（低于首选项中的阈值）</translation>
    </message>
</context>
<context>
    <name>SimKeys</name>
    <message>
        <source>Faster forward by a large step (+20 units/s)</source>
        <translation>向前加速，大步长（+20 单位/秒）</translation>
    </message>
    <message>
        <source>Slower (or backward) by a large step (-20 units/s)</source>
        <translation>减速（或后退），大步长（-20 单位/秒）</translation>
    </message>
    <message>
        <source>Faster forward by a small step (+5 units/s)</source>
        <translation>向前加速，小步长（+5 单位/秒）</translation>
    </message>
    <message>
        <source>Slower (or backward) by a small step (-5 units/s)</source>
        <translation>减速（或后退），小步长（-5 单位/秒）</translation>
    </message>
    <message>
        <source>Turn left by a large step (+0.2 rad/s)</source>
        <translation>左转，大步长（+0.2 rad/s）</translation>
    </message>
    <message>
        <source>Turn right by a large step (-0.2 rad/s)</source>
        <translation>右转，大步长（-0.2 rad/s）</translation>
    </message>
    <message>
        <source>Turn left by a small step (+0.05 rad/s)</source>
        <translation>左转，小步长（+0.05 rad/s）</translation>
    </message>
    <message>
        <source>Turn right by a small step (-0.05 rad/s)</source>
        <translation>右转，小步长（-0.05 rad/s）</translation>
    </message>
    <message>
        <source>Stop (v = 0, omega = 0)</source>
        <translation>停止（v = 0，omega = 0）</translation>
    </message>
    <message>
        <source>Robot close-up / whole scene (close-up only in experiment mode)</source>
        <translation>机器人特写 / 整个场景（实验模式下仅特写）</translation>
    </message>
    <message>
        <source>Pause / go on</source>
        <translation>暂停 / 继续</translation>
    </message>
    <message>
        <source>One step (while paused)</source>
        <translation>单步（暂停时）</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan on the picture / off (autonomous mode)</source>
        <translation>在图上显示/隐藏导航器的触觉地图和路径规划（自主模式）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tactile Workbench: tactile-navigation research desktop</source>
        <translation>触觉工作台：触觉导航研究桌面程序</translation>
    </message>
    <message>
        <source>Open the run database DB (default: the last one used).</source>
        <translation>打开运行数据库 DB（默认：上次使用的数据库）。</translation>
    </message>
    <message>
        <source>Open the run named NAME.</source>
        <translation>打开名为 NAME 的运行。</translation>
    </message>
    <message>
        <source>Put the cursor on step K.</source>
        <translation>将光标置于第 K 步。</translation>
    </message>
    <message>
        <source>Render the window (or with --sweep the results window) at 1600x1000 to the PNG file FILE, then quit.</source>
        <translation>将窗口（使用 --sweep 时为结果窗口）以 1600x1000 渲染为 PNG 文件 FILE，然后退出。</translation>
    </message>
    <message>
        <source>Open the results of the stored sweep ID (needs --db).</source>
        <translation>打开已保存的扫描 ID 的结果（需要 --db）。</translation>
    </message>
    <message>
        <source>--step needs a step number, got &apos;%1&apos;</source>
        <translation>--step 需要一个步数，收到的是“%1”</translation>
    </message>
    <message>
        <source>--run needs --db</source>
        <translation>--run 需要 --db</translation>
    </message>
    <message>
        <source>--sweep needs --db</source>
        <translation>--sweep 需要 --db</translation>
    </message>
    <message>
        <source>--model needs --run</source>
        <translation>--model 需要 --run</translation>
    </message>
    <message>
        <source>--sweep needs a sweep id, got &apos;%1&apos;</source>
        <translation>--sweep 需要一个扫描 ID，收到的是“%1”</translation>
    </message>
    <message>
        <source>%1: no such database</source>
        <translation>%1：没有此数据库</translation>
    </message>
    <message>
        <source>Open the simulator window on SCENE (a built-in scene, a scene JSON file or random:N:SEED); runs go into --db (or the last database).</source>
        <translation>在场景 SCENE（内置场景、场景 JSON 文件或 random:N:SEED）上打开模拟器窗口；运行保存到 --db（或上次使用的数据库）。</translation>
    </message>
    <message>
        <source>With --simulate: practice (default), experiment or autonomous.</source>
        <translation>与 --simulate 一起使用：practice（练习，默认）、experiment（实验）或 autonomous（自主）。</translation>
    </message>
    <message>
        <source>With --simulate: the subject&apos;s name.</source>
        <translation>与 --simulate 一起使用：受试者姓名。</translation>
    </message>
    <message>
        <source>With --simulate: start a run and replay the v, omega commands of the run file FILE, one a step.</source>
        <translation>与 --simulate 一起使用：开始一次运行，并逐步重放运行文件 FILE 中的 v、omega 指令，每步一条。</translation>
    </message>
    <message>
        <source>With --simulate: steps per second (default 10; 0 as fast as possible).</source>
        <translation>与 --simulate 一起使用：每秒步数（默认 10；0 表示尽可能快）。</translation>
    </message>
    <message>
        <source>With --simulate: show the data panel.</source>
        <translation>与 --simulate 一起使用：显示数据面板。</translation>
    </message>
    <message>
        <source>With --simulate: show the whole scene where allowed.</source>
        <translation>与 --simulate 一起使用：在允许时显示整个场景。</translation>
    </message>
    <message>
        <source>no stored model named &apos;%1&apos;</source>
        <translation>没有名为“%1”的已保存模型</translation>
    </message>
    <message>
        <source>--mode must be practice, experiment or autonomous, got &apos;%1&apos;</source>
        <translation>--mode 必须是 practice、experiment 或 autonomous，收到的是“%1”</translation>
    </message>
    <message>
        <source>--rate needs a number &gt;= 0, got &apos;%1&apos;</source>
        <translation>--rate 需要一个 &gt;= 0 的数，收到的是“%1”</translation>
    </message>
    <message>
        <source>Show the stored model NAME&apos;s predictions under the labels (needs --run); with --simulate --mode autonomous: the navigator&apos;s model.</source>
        <translation>在标注下方显示已存储模型 NAME 的预测（需要 --run）；与 --simulate --mode autonomous 一起使用时：导航器使用的模型。</translation>
    </message>
    <message>
        <source>With --simulate --mode autonomous: what the navigator&apos;s status comes from, model (with --model), truth or bumper, as tactile navigate --status.</source>
        <translation>与 --simulate --mode autonomous 一起使用：导航器状态的来源，model（需 --model）、truth 或 bumper，同 tactile navigate --status。</translation>
    </message>
    <message>
        <source>--status needs --simulate and --mode autonomous</source>
        <translation>--status 需要 --simulate 和 --mode autonomous</translation>
    </message>
    <message>
        <source>--status %1 takes no --model</source>
        <translation>--status %1 不接受 --model</translation>
    </message>
    <message>
        <source>--status must be model, truth or bumper, got &apos;%1&apos;</source>
        <translation>--status 必须是 model、truth 或 bumper，而不是 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--status model needs --model NAME</source>
        <translation>--status model 需要 --model NAME</translation>
    </message>
    <message>
        <source>no display to open a window on (DISPLAY and WAYLAND_DISPLAY are not set). Run it in a desktop session, or with --screenshot FILE to render without a display; the command-line tool is tactile.</source>
        <translation>没有可打开窗口的显示（未设置 DISPLAY 和 WAYLAND_DISPLAY）。请在桌面会话中运行，或使用 --screenshot FILE 在无显示的情况下渲染；命令行工具是 tactile。</translation>
    </message>
    <message>
        <source>With --simulate --mode experiment: the seed of start and goal; --mode autonomous: the seed of the start (as tactile navigate --seeds); 0: the scene&apos;s own start and goal.</source>
        <translation>与 --simulate --mode experiment 一起使用：起点和目标的种子；--mode autonomous：起点的种子（与 tactile navigate --seeds 相同）；0：场景自身的起点和目标。</translation>
    </message>
    <message>
        <source>--seed needs a number &gt;= 0, got &apos;%1&apos;</source>
        <translation>--seed 需要一个 &gt;= 0 的数，收到的是“%1”</translation>
    </message>
</context>
<context>
    <name>tactile::gui::ExperimentPanel</name>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Strategies</source>
        <translation>策略</translation>
    </message>
    <message>
        <source>Go Straight</source>
        <translation>直行</translation>
    </message>
    <message>
        <source>Head to Destination</source>
        <translation>驶向目标</translation>
    </message>
    <message>
        <source>Check Contact</source>
        <translation>检查接触</translation>
    </message>
    <message>
        <source>Follow Wall</source>
        <translation>沿墙行驶</translation>
    </message>
    <message>
        <source>Move through Wall</source>
        <translation>穿过墙体</translation>
    </message>
    <message>
        <source>Right U Turn</source>
        <translation>右掉头</translation>
    </message>
    <message>
        <source>Left U Turn</source>
        <translation>左掉头</translation>
    </message>
    <message>
        <source>Hole, %1 wide</source>
        <translation>缺口，宽 %1</translation>
    </message>
    <message>
        <source>Undecided</source>
        <translation>未定</translation>
    </message>
</context>
<context>
    <name>tactile::gui::HistoryView</name>
    <message>
        <source>labelled</source>
        <translation>已标注</translation>
    </message>
    <message>
        <source>moved</source>
        <translation>已移动</translation>
    </message>
    <message>
        <source>deleted</source>
        <translation>已删除</translation>
    </message>
    <message>
        <source>undone</source>
        <translation>已撤销</translation>
    </message>
    <message>
        <source>redone</source>
        <translation>已重做</translation>
    </message>
    <message>
        <source>imported</source>
        <translation>已导入</translation>
    </message>
    <message>
        <source>from truth</source>
        <translation>来自真值</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>已恢复</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>修订</translation>
    </message>
    <message>
        <source>Time (UTC)</source>
        <translation>时间 (UTC)</translation>
    </message>
    <message>
        <source>Annotator</source>
        <translation>标注者</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>修改</translation>
    </message>
    <message>
        <source>Open a label set and a run to see who changed its labels.</source>
        <translation>打开一个标签集和一次运行，查看谁修改了它的标签。</translation>
    </message>
    <message>
        <source>No edit of these labels is recorded yet.</source>
        <translation>这些标签尚无修改记录。</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>%1 %2-%3 by %4</source>
        <translation>%1 %2-%3，由 %4</translation>
    </message>
    <message>
        <source>The steps were unlabelled before.</source>
        <translation>这些步之前未标注。</translation>
    </message>
    <message>
        <source>Before: %1</source>
        <translation>之前：%1</translation>
    </message>
    <message>
        <source>%1 %2-%3: %4 (%5)</source>
        <translation>%1 %2-%3：%4（%5）</translation>
    </message>
    <message>
        <source>cleared or several</source>
        <translation>已清除或多个</translation>
    </message>
    <message>
        <source>One edit of set &apos;%1&apos; on this run.</source>
        <translation>集 &apos;%1&apos; 在此运行上的 1 次修改。</translation>
    </message>
    <message>
        <source>%1 edits of set &apos;%2&apos; on this run, newest first.</source>
        <translation>集 &apos;%2&apos; 在此运行上的 %1 次修改，最新的在前。</translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelModel</name>
    <message>
        <source>Label steps %1-%2 as %3</source>
        <translation>将第 %1–%2 步标注为%3</translation>
    </message>
    <message>
        <source>Move %1 segment to steps %2-%3</source>
        <translation>将%1片段移至第 %2–%3 步</translation>
    </message>
    <message>
        <source>Delete segment</source>
        <translation>删除片段</translation>
    </message>
    <message>
        <source> The run&apos;s labels are reloaded.</source>
        <translation> 已重新加载该运行的标签。</translation>
    </message>
    <message>
        <source>%1 changed %2 steps %3-%4 (%5)</source>
        <translation>%1 修改了 %2 的第 %3-%4 步（%5）</translation>
    </message>
    <message>
        <source>someone</source>
        <translation>某人</translation>
    </message>
    <message>
        <source>Label steps %1-%2 from the model</source>
        <translation>用模型标注第 %1-%2 步</translation>
    </message>
    <message>
        <source>no chosen model covers %1: choose the group of a model (Learn &gt; Show Predictions shows which groups each covers)</source>
        <translation>没有所选模型覆盖 %1：请选择某个模型覆盖的组（学习 &gt; 显示预测会列出每个模型覆盖的组）</translation>
    </message>
</context>
<context>
    <name>tactile::gui::LabelPanelView</name>
    <message>
        <source>Label set</source>
        <translation>标签集</translation>
    </message>
    <message>
        <source>The label set being edited; choose another to open it</source>
        <translation>正在编辑的标签集；选择另一个即可打开</translation>
    </message>
    <message>
        <source>New...</source>
        <translation>新建...</translation>
    </message>
    <message>
        <source>Save As...</source>
        <translation>另存为...</translation>
    </message>
    <message>
        <source>Import...</source>
        <translation>导入...</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>导出...</translation>
    </message>
    <message>
        <source>Apply to</source>
        <translation>应用于</translation>
    </message>
    <message>
        <source>Selected group</source>
        <translation>选中的组</translation>
    </message>
    <message>
        <source>Checked groups</source>
        <translation>勾选的组</translation>
    </message>
    <message>
        <source>Groups in contact</source>
        <translation>有接触的组</translation>
    </message>
    <message>
        <source>Label the %1 group (with &quot;Checked groups&quot;)</source>
        <translation>标注 %1 组（配合“勾选的组”）</translation>
    </message>
    <message>
        <source>Classes (keys 1-5)</source>
        <translation>类别（按键 1–5）</translation>
    </message>
    <message>
        <source>Label the selected steps as %1 (key %2)</source>
        <translation>将选中的步标注为%1（按键 %2）</translation>
    </message>
    <message>
        <source>At the cursor</source>
        <translation>光标处</translation>
    </message>
    <message>
        <source>Delete segment (Del)</source>
        <translation>删除片段（Del）</translation>
    </message>
    <message>
        <source>Selection:</source>
        <translation>选区：</translation>
    </message>
    <message>
        <source>Segment:</source>
        <translation>片段：</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>组</translation>
    </message>
    <message>
        <source>Agree</source>
        <translation>一致率</translation>
    </message>
    <message>
        <source>Kappa</source>
        <translation>Kappa</translation>
    </message>
    <message>
        <source>Open a run first.</source>
        <translation>请先打开一个运行。</translation>
    </message>
    <message>
        <source>Create or open a label set first.</source>
        <translation>请先新建或打开一个标签集。</translation>
    </message>
    <message>
        <source>No segment of the selected group under the cursor.</source>
        <translation>光标处没有选中组的片段。</translation>
    </message>
    <message>
        <source>(no label set)</source>
        <translation>（无标签集）</translation>
    </message>
    <message>
        <source>New label set</source>
        <translation>新建标签集</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>No label set is open.</source>
        <translation>没有打开的标签集。</translation>
    </message>
    <message>
        <source>Save label set as</source>
        <translation>标签集另存为</translation>
    </message>
    <message>
        <source>Name of the copy:</source>
        <translation>副本名称：</translation>
    </message>
    <message>
        <source> copy</source>
        <translation> 副本</translation>
    </message>
    <message>
        <source>Import labels</source>
        <translation>导入标签</translation>
    </message>
    <message>
        <source>Label files (*.csv *.json);;All files (*)</source>
        <translation>标签文件 (*.csv *.json);;所有文件 (*)</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n segment(s)</source>
        <translation>
            <numerusform>已导入 %n 个片段</numerusform>
        </translation>
    </message>
    <message>
        <source>Export labels</source>
        <translation>导出标签</translation>
    </message>
    <message>
        <source>CSV (*.csv);;JSON (*.json)</source>
        <translation>CSV (*.csv);;JSON (*.json)</translation>
    </message>
    <message>
        <source>Exported %1 to %2</source>
        <translation>已将 %1 导出到 %2</translation>
    </message>
    <message numerus="yes">
        <source>steps %1-%2 (%n step(s))</source>
        <translation>
            <numerusform>第 %1–%2 步（共 %n 步）</numerusform>
        </translation>
    </message>
    <message>
        <source>none (an edit labels the current step)</source>
        <translation>无（编辑将标注当前步）</translation>
    </message>
    <message>
        <source>%1: unlabelled</source>
        <translation>%1：未标注</translation>
    </message>
    <message>
        <source>%1: %2, steps %3-%4</source>
        <translation>%1：%2，第 %3–%4 步</translation>
    </message>
    <message>
        <source>Compare the labels with the run&apos;s truth or with another label set (another annotator)</source>
        <translation>将标签与运行的真值或另一个标签集（另一位标注者）进行比较</translation>
    </message>
    <message>
        <source>Chance</source>
        <translation>偶然一致率</translation>
    </message>
    <message>
        <source>Share of the steps both sides label on which they give the same class</source>
        <translation>在双方都已标注的步中，双方给出相同类别的比例</translation>
    </message>
    <message>
        <source>Agreement expected by chance from each side&apos;s class shares</source>
        <translation>根据双方各自的类别占比，偶然情况下预期的一致率</translation>
    </message>
    <message>
        <source>Cohen&apos;s kappa = (agree - chance) / (100 % - chance): 0 when the agreement is no better than chance, 1 when perfect; &apos;-&apos; when chance is 100 % (one class throughout)</source>
        <translation>Cohen&apos;s kappa = (一致率 − 偶然一致率) / (100 % − 偶然一致率)：一致程度不优于偶然时为 0，完全一致时为 1；偶然一致率为 100 %（始终只有一个类别）时显示“-”</translation>
    </message>
    <message>
        <source>Agreement with</source>
        <translation>比较对象</translation>
    </message>
    <message>
        <source>truth</source>
        <translation>真值</translation>
    </message>
    <message>
        <source>label set %1</source>
        <translation>标签集 %1</translation>
    </message>
    <message>
        <source>No step is labelled on both sides</source>
        <translation>没有双方都已标注的步</translation>
    </message>
    <message numerus="yes">
        <source>Undefined: both sides use one and the same class on all %n step(s), so chance agreement is 100 %</source>
        <translation>
            <numerusform>未定义：双方在全部 %n 步上都使用同一个类别，因此偶然一致率为 100 %</numerusform>
        </translation>
    </message>
    <message>
        <source>No group is in contact here: nothing to label.</source>
        <translation>此处没有组处于接触状态：无可标注。</translation>
    </message>
    <message>
        <source>No group to label: tick a group.</source>
        <translation>没有要标注的组：请勾选一个组。</translation>
    </message>
    <message>
        <source>Labelled steps %1-%2 as %3 in %4</source>
        <translation>已将步 %1-%2 标注为 %3，组：%4</translation>
    </message>
    <message>
        <source>%1 of %2 steps agree (%3). Two annotators labelling at random with these class shares would agree on %4. Kappa %5 says how much better than chance they agree: 1 fully, 0 no better than chance.</source>
        <translation>%2 步中有 %1 步一致（%3）。两位按这些类别比例随机标注的标注者会在 %4 上一致。Kappa %5 表示一致程度比随机好多少：1 为完全一致，0 为不比随机好。</translation>
    </message>
</context>
<context>
    <name>tactile::gui::MainWindow</name>
    <message>
        <source>Predictions: %1</source>
        <translation>预测：%1</translation>
    </message>
    <message numerus="yes">
        <source>Predictions shown: %n step(s) disagree with the labels (N: next)</source>
        <translation>
            <numerusform>已显示预测：%n 步与标签不一致（N：下一处）</numerusform>
        </translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Route</source>
        <translation>路线</translation>
    </message>
    <message>
        <source>Labels</source>
        <translation>标签</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open Database...</source>
        <translation>打开数据库(&amp;O)...</translation>
    </message>
    <message>
        <source>&amp;New Database...</source>
        <translation>新建数据库(&amp;N)...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Import Runs...</source>
        <translation>导入运行(&amp;I)...</translation>
    </message>
    <message>
        <source>Export &amp;Labels...</source>
        <translation>导出标签(&amp;L)...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Label as %1</source>
        <translation>标注为%1</translation>
    </message>
    <message>
        <source>&amp;Delete Segment</source>
        <translation>删除片段(&amp;D)</translation>
    </message>
    <message>
        <source>Move Segment Start Left</source>
        <translation>片段起点左移</translation>
    </message>
    <message>
        <source>Move Segment Start Right</source>
        <translation>片段起点右移</translation>
    </message>
    <message>
        <source>Move Segment End Left</source>
        <translation>片段终点左移</translation>
    </message>
    <message>
        <source>Move Segment End Right</source>
        <translation>片段终点右移</translation>
    </message>
    <message>
        <source>Clear Selection</source>
        <translation>清除选区</translation>
    </message>
    <message>
        <source>&amp;Go</source>
        <translation>转到(&amp;G)</translation>
    </message>
    <message>
        <source>Next Step</source>
        <translation>下一步</translation>
    </message>
    <message>
        <source>Previous Step</source>
        <translation>上一步</translation>
    </message>
    <message>
        <source>Forward 10 Steps</source>
        <translation>前进 10 步</translation>
    </message>
    <message>
        <source>Back 10 Steps</source>
        <translation>后退 10 步</translation>
    </message>
    <message>
        <source>Forward 100 Steps</source>
        <translation>前进 100 步</translation>
    </message>
    <message>
        <source>Back 100 Steps</source>
        <translation>后退 100 步</translation>
    </message>
    <message>
        <source>Forward One Screen</source>
        <translation>前进一屏</translation>
    </message>
    <message>
        <source>Back One Screen</source>
        <translation>后退一屏</translation>
    </message>
    <message>
        <source>First Step</source>
        <translation>第一步</translation>
    </message>
    <message>
        <source>Last Step</source>
        <translation>最后一步</translation>
    </message>
    <message>
        <source>Play / Pause</source>
        <translation>播放 / 暂停</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene</source>
        <translation>机器人特写 / 整个场景</translation>
    </message>
    <message>
        <source>Colour Route by Label</source>
        <translation>按标签为路线着色</translation>
    </message>
    <message>
        <source>Heatmap: Normal</source>
        <translation>热图：法向力</translation>
    </message>
    <message>
        <source>Heatmap: Shear</source>
        <translation>热图：剪切力</translation>
    </message>
    <message>
        <source>Heatmap: Magnitude</source>
        <translation>热图：合力大小</translation>
    </message>
    <message>
        <source>Zoom to Whole Run</source>
        <translation>缩放至整个运行</translation>
    </message>
    <message>
        <source>&amp;Learn</source>
        <translation>学习(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Train and Sweep...</source>
        <translation>训练与扫描(&amp;T)...</translation>
    </message>
    <message>
        <source>Open &amp;Sweep Results...</source>
        <translation>打开扫描结果(&amp;S)...</translation>
    </message>
    <message>
        <source>Show &amp;Predictions...</source>
        <translation>显示预测(&amp;P)...</translation>
    </message>
    <message>
        <source>&amp;Hide Predictions</source>
        <translation>隐藏预测(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Next Disagreement</source>
        <translation>下一处不一致(&amp;N)</translation>
    </message>
    <message>
        <source>Pre&amp;vious Disagreement</source>
        <translation>上一处不一致(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Export Model...</source>
        <translation>导出模型(&amp;E)...</translation>
    </message>
    <message>
        <source>&amp;Import Model...</source>
        <translation>导入模型(&amp;I)...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About Tactile Workbench</source>
        <translation>关于触觉工作台(&amp;A)</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Open or create a database before importing runs.</source>
        <translation>导入运行前请先打开或新建数据库。</translation>
    </message>
    <message>
        <source>Importing runs...</source>
        <translation>正在导入运行...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message numerus="yes">
        <source>Importing %n run file(s)...</source>
        <translation>
            <numerusform>正在导入 %n 个运行文件...</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n run(s)</source>
        <translation>
            <numerusform>已导入 %n 个运行</numerusform>
        </translation>
    </message>
    <message>
        <source>; cancelled</source>
        <translation>；已取消</translation>
    </message>
    <message numerus="yes">
        <source>; %n file(s) not imported: </source>
        <translation>
            <numerusform>；%n 个文件未导入：</numerusform>
        </translation>
    </message>
    <message>
        <source>New database</source>
        <translation>新建数据库</translation>
    </message>
    <message>
        <source>Tactile databases (*.db);;All files (*)</source>
        <translation>触觉数据库 (*.db);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open database</source>
        <translation>打开数据库</translation>
    </message>
    <message>
        <source>Tactile databases (*.db *.sqlite);;All files (*)</source>
        <translation>触觉数据库 (*.db *.sqlite);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Import runs</source>
        <translation>导入运行</translation>
    </message>
    <message>
        <source>Run files (*.csv);;All files (*)</source>
        <translation>运行文件 (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Not a run file, folder or database: %1</source>
        <translation>不是运行文件、文件夹或数据库：%1</translation>
    </message>
    <message numerus="yes">
        <source>Drop one database at a time (%n dropped).</source>
        <translation>
            <numerusform>一次只能拖放一个数据库（拖放了 %n 个）。</numerusform>
        </translation>
    </message>
    <message>
        <source>Error: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <source>Tactile Workbench</source>
        <translation>触觉工作台</translation>
    </message>
    <message>
        <source>  |  selected %1-%2</source>
        <translation>  |  已选 %1–%2</translation>
    </message>
    <message>
        <source>No run open</source>
        <translation>未打开运行</translation>
    </message>
    <message>
        <source>No database open</source>
        <translation>未打开数据库</translation>
    </message>
    <message>
        <source>Label set: %1</source>
        <translation>标签集：%1</translation>
    </message>
    <message>
        <source>No label set</source>
        <translation>无标签集</translation>
    </message>
    <message>
        <source>About Tactile Workbench</source>
        <translation>关于触觉工作台</translation>
    </message>
    <message>
        <source>Tactile Workbench %1
Research workbench for tactile-based mobile-robot navigation.</source>
        <translation>触觉工作台 %1
基于触觉的移动机器人导航研究平台。</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>退出</translation>
    </message>
    <message>
        <source>A sweep or training is running. Cancel it and quit? Finished sweep cells stay stored.</source>
        <translation>扫描或训练正在进行。要取消并退出吗？已完成的扫描单元会保留。</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored</source>
        <translation>模型“%1”已保存</translation>
    </message>
    <message>
        <source>Open a database first</source>
        <translation>请先打开数据库</translation>
    </message>
    <message>
        <source>The database has no sweep yet: Learn &gt; Train and Sweep</source>
        <translation>数据库中还没有扫描：学习 &gt; 训练与扫描</translation>
    </message>
    <message>
        <source>%1: %2 (%3 cells, %4)</source>
        <translation>%1：%2（%3 个单元，%4）</translation>
    </message>
    <message>
        <source>Open Sweep Results</source>
        <translation>打开扫描结果</translation>
    </message>
    <message>
        <source>Sweep:</source>
        <translation>扫描：</translation>
    </message>
    <message>
        <source>The database has no model yet</source>
        <translation>数据库中还没有模型</translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation>导出模型</translation>
    </message>
    <message>
        <source>Model:</source>
        <translation>模型：</translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation>模型文件 (*.json)</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; written to %2</source>
        <translation>模型“%1”已写入 %2</translation>
    </message>
    <message>
        <source>Open a run first</source>
        <translation>请先打开一个运行</translation>
    </message>
    <message>
        <source>The database has no model yet: Learn &gt; Train and Sweep</source>
        <translation>数据库中还没有模型：学习 &gt; 训练与扫描</translation>
    </message>
    <message>
        <source>No predictions shown: Learn &gt; Show Predictions</source>
        <translation>未显示预测：学习 &gt; 显示预测</translation>
    </message>
    <message>
        <source>The model agrees with the labels everywhere</source>
        <translation>模型与标签处处一致</translation>
    </message>
    <message>
        <source>Step %1, group %2: the model says %3 (%4 %), the label %5</source>
        <translation>第 %1 步，%2 组：模型判为%3（%4 %），标签为%5</translation>
    </message>
    <message>
        <source>Import Model</source>
        <translation>导入模型</translation>
    </message>
    <message>
        <source>Store as:</source>
        <translation>保存为：</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored from %2</source>
        <translation>已从 %2 保存模型“%1”</translation>
    </message>
    <message>
        <source>Navigator</source>
        <translation>导航器</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Preferences saved</source>
        <translation>首选项已保存</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>首选项(&amp;P)...</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>Step %1 of %2 steps</source>
        <translation>第 %1 步，共 %2 步</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>New &amp;Simulation...</source>
        <translation>新建模拟(&amp;S)...</translation>
    </message>
    <message>
        <source>Import &amp;MCAP...</source>
        <translation>导入 &amp;MCAP...</translation>
    </message>
    <message>
        <source>Export &amp;Run</source>
        <translation>导出运行(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;MCAP...</source>
        <translation>&amp;MCAP...</translation>
    </message>
    <message>
        <source>Drop one MCAP file at a time, on its own.</source>
        <translation>请一次只拖放一个 MCAP 文件，且不要与其他文件一起拖放。</translation>
    </message>
    <message>
        <source>An MCAP export or import is already running</source>
        <translation>已有 MCAP 导出或导入正在进行</translation>
    </message>
    <message>
        <source>Exporting &apos;%1&apos; to %2...</source>
        <translation>正在将“%1”导出到 %2...</translation>
    </message>
    <message>
        <source>MCAP export cancelled</source>
        <translation>MCAP 导出已取消</translation>
    </message>
    <message>
        <source>Export Run as MCAP</source>
        <translation>将运行导出为 MCAP</translation>
    </message>
    <message numerus="yes">
        <source>Run written to %1 (%n step(s))</source>
        <translation>
            <numerusform>运行已写入 %1（%n 步）</numerusform>
        </translation>
    </message>
    <message>
        <source>Import MCAP</source>
        <translation>导入 MCAP</translation>
    </message>
    <message>
        <source>MCAP files (*.mcap);;All files (*)</source>
        <translation>MCAP 文件 (*.mcap);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Importing %1...</source>
        <translation>正在导入 %1...</translation>
    </message>
    <message numerus="yes">
        <source>Imported run &apos;%1&apos; (%n step(s))</source>
        <translation>
            <numerusform>已导入运行“%1”（%n 步）</numerusform>
        </translation>
    </message>
    <message>
        <source>Undone: %1</source>
        <translation>已撤销：%1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>已重做：%1</translation>
    </message>
    <message>
        <source>Labels changed by others: %1</source>
        <translation>他人修改的标签：%1</translation>
    </message>
    <message>
        <source>Reconnected to %1</source>
        <translation>已重新连接到 %1</translation>
    </message>
    <message>
        <source>History</source>
        <translation>历史</translation>
    </message>
    <message>
        <source>Open &amp;Server...</source>
        <translation>打开服务器(&amp;S)...</translation>
    </message>
    <message>
        <source>Open Server</source>
        <translation>打开服务器</translation>
    </message>
    <message>
        <source>PostgreSQL address, e.g. postgresql://anna@lab-server/tactile
(the password is asked when the server wants one, or comes from ~/.pgpass)</source>
        <translation>PostgreSQL 地址，例如 postgresql://anna@lab-server/tactile
（服务器需要密码时会询问，或取自 ~/.pgpass）</translation>
    </message>
    <message>
        <source>%1 is not a server address (postgresql://USER@HOST/DATABASE)</source>
        <translation>%1 不是服务器地址（postgresql://用户@主机/数据库）</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>密码</translation>
    </message>
    <message>
        <source>Password for %1:</source>
        <translation>%1 的密码：</translation>
    </message>
    <message>
        <source>Assign Run</source>
        <translation>分配运行</translation>
    </message>
    <message>
        <source>Annotator to assign %1 to:</source>
        <translation>将 %1 分配给的标注者：</translation>
    </message>
    <message>
        <source>Set your annotator name in Preferences first.</source>
        <translation>请先在首选项中设置您的标注者名称。</translation>
    </message>
    <message>
        <source>%1 assigned to %2: %3</source>
        <translation>%1 已分配给 %2：%3</translation>
    </message>
    <message>
        <source>Your role on this database: %1</source>
        <translation>您在此数据库中的角色：%1</translation>
    </message>
    <message>
        <source>admin</source>
        <translation>管理员</translation>
    </message>
    <message>
        <source>researcher</source>
        <translation>研究者</translation>
    </message>
    <message>
        <source>annotator</source>
        <translation>标注者</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>只读</translation>
    </message>
    <message>
        <source>&amp;Label from Model</source>
        <translation>用模型标注(&amp;L)</translation>
    </message>
    <message>
        <source>Open a run and a label set first.</source>
        <translation>请先打开一次运行和一个标签集。</translation>
    </message>
    <message>
        <source>Show a model&apos;s predictions first (Learn &gt; Show Predictions): their model&apos;s decisions are what Label from Model writes.</source>
        <translation>请先显示某个模型的预测（学习 &gt; 显示预测）：“用模型标注”写入的就是该模型的决策。</translation>
    </message>
    <message>
        <source>Steps %1-%2 labelled from the model (Undo takes it back)</source>
        <translation>已用模型标注第 %1-%2 步（撤销可还原）</translation>
    </message>
    <message>
        <source>Next &amp;Doubt</source>
        <translation>下一个疑点(&amp;D)</translation>
    </message>
    <message>
        <source>The model is at least %1 % sure everywhere</source>
        <translation>模型在各处的把握至少为 %1 %</translation>
    </message>
    <message>
        <source>Step %1, group %2: the model is unsure (%3 % %4)</source>
        <translation>第 %1 步，组 %2：模型不确定（%3 % %4）</translation>
    </message>
    <message>
        <source>Lost the connection to the database; trying again every 3 seconds, and edits are not stored meanwhile (%1)</source>
        <translation>与数据库的连接已断开；每 3 秒重试一次，在此期间编辑不会被保存（%1）</translation>
    </message>
    <message>
        <source>Predictions shown; this run has no labels in the set yet (Ctrl+L labels the steps in view from the model)</source>
        <translation>已显示预测；此运行在该标签集中还没有标签（Ctrl+L 用模型为可见的步骤加标签）</translation>
    </message>
</context>
<context>
    <name>tactile::gui::McapExportDialog</name>
    <message>
        <source>Export Run as MCAP</source>
        <translation>将运行导出为 MCAP</translation>
    </message>
    <message>
        <source>Run:</source>
        <translation>运行：</translation>
    </message>
    <message>
        <source>Label sets:</source>
        <translation>标签集：</translation>
    </message>
    <message>
        <source>none in this database</source>
        <translation>此数据库中没有</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(无)</translation>
    </message>
    <message>
        <source>The model&apos;s online decisions go on /decisions/MODEL</source>
        <translation>模型的在线决策写入 /decisions/MODEL</translation>
    </message>
    <message>
        <source>Model decisions:</source>
        <translation>模型决策：</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <source>Opens in Foxglove and Lichtblick: the readings, pose, command, truth, the chosen label sets and the model&apos;s decisions, one message per step, and the scene&apos;s walls.</source>
        <translation>可在 Foxglove 和 Lichtblick 中打开：读数、位姿、指令、真值、所选标签集和模型的决策，每步一条消息，以及场景的墙壁。</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>MCAP files (*.mcap);;All files (*)</source>
        <translation>MCAP 文件 (*.mcap);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::McapMappingDialog</name>
    <message>
        <source>Import ROS 2 Bag</source>
        <translation>导入 ROS 2 Bag</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; is not an export of this program. Choose which of its topics make the run: one step per message on the tactile topic; pose and command are the latest messages before it.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; 不是本程序的导出文件。请选择构成运行的话题：触觉话题上每条消息为一步；位姿和指令取其之前的最新消息。</translation>
    </message>
    <message>
        <source>Topic</source>
        <translation>话题</translation>
    </message>
    <message>
        <source>Schema</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>Message encoding</source>
        <translation>消息编码</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>消息数</translation>
    </message>
    <message>
        <source>44 normals, then 44 shears</source>
        <translation>44 个法向值，然后 44 个剪切值</translation>
    </message>
    <message>
        <source>interleaved: n0, s0, n1, s1, ...</source>
        <translation>交错：n0, s0, n1, s1, ...</translation>
    </message>
    <message>
        <source>Scene units per bag unit: 1000 for a bag in metres (scenes are in mm)</source>
        <translation>每个 bag 单位对应的场景单位：bag 以米为单位时为 1000（场景以毫米为单位）</translation>
    </message>
    <message>
        <source>Tactile readings:</source>
        <translation>触觉读数：</translation>
    </message>
    <message>
        <source>Layout of the 88 values:</source>
        <translation>88 个值的排列：</translation>
    </message>
    <message>
        <source>Pose:</source>
        <translation>位姿：</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>指令：</translation>
    </message>
    <message>
        <source>Blocked flag:</source>
        <translation>阻挡标志：</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>比例：</translation>
    </message>
    <message>
        <source>Run name:</source>
        <translation>运行名称：</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Channels in the file:</source>
        <translation>文件中的通道：</translation>
    </message>
</context>
<context>
    <name>tactile::gui::ModelPickerDialog</name>
    <message>
        <source>Show Predictions</source>
        <translation>显示预测</translation>
    </message>
    <message>
        <source>A model per group</source>
        <translation>每组一个模型</translation>
    </message>
    <message>
        <source>Model:</source>
        <translation>模型：</translation>
    </message>
    <message>
        <source>The timeline shows each group&apos;s predicted class under its labels, pale where the model is unsure, and marks where it disagrees with the labels (N: next disagreement).</source>
        <translation>时间轴在每组标签下方显示预测类别，模型不确定处颜色较浅，并标出与标签不一致之处（N：下一处不一致）。</translation>
    </message>
    <message>
        <source>%1 (all groups)</source>
        <translation>%1（所有组）</translation>
    </message>
    <message>
        <source>%1 (%2 only)</source>
        <translation>%1（仅 %2）</translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorPanelView</name>
    <message>
        <source>This run has no navigator columns. Runs written by &apos;tactile navigate&apos; have them.</source>
        <translation>此运行没有导航器列。由“tactile navigate”写入的运行才有这些列。</translation>
    </message>
    <message>
        <source>Command set:</source>
        <translation>指令集：</translation>
    </message>
    <message>
        <source>Current control mode:</source>
        <translation>当前控制模式：</translation>
    </message>
    <message>
        <source>Status:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <source>Status-%1:</source>
        <translation>状态-%1：</translation>
    </message>
</context>
<context>
    <name>tactile::gui::NavigatorStripView</name>
    <message>
        <source>strategy</source>
        <translation>策略</translation>
    </message>
    <message>
        <source>status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation>第 %1 步：%2</translation>
    </message>
</context>
<context>
    <name>tactile::gui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <source>Follow the system</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <source>e.g. your initials</source>
        <translation>例如您的姓名缩写</translation>
    </message>
    <message>
        <source>Stored with every label segment you write and in label exports (annotator column)</source>
        <translation>随您写入的每个标签片段一起保存，也写入标签导出文件（annotator 列）</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Height of each label, truth and model row in the timelines</source>
        <translation>时间轴中每个标签行、真值行和模型行的高度</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <source>A new language applies at the next start.</source>
        <translation>新语言将在下次启动时生效。</translation>
    </message>
    <message>
        <source>&amp;Annotator:</source>
        <translation>标注者(&amp;A)：</translation>
    </message>
    <message>
        <source>Timeline &amp;row height:</source>
        <translation>时间轴行高(&amp;R)：</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Learn &gt; Next Doubt (D) stops where the model&apos;s posterior of its own prediction is below this</source>
        <translation>学习 &gt; 下一个疑点 (D) 停在模型对自身预测的后验概率低于此值之处</translation>
    </message>
    <message>
        <source>Model &amp;unsure below:</source>
        <translation>模型不确定阈值(&amp;U)：</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RouteView</name>
    <message>
        <source>hole %1</source>
        <translation>缺口 %1</translation>
    </message>
    <message>
        <source>hole %1 wide</source>
        <translation>缺口宽 %1</translation>
    </message>
    <message>
        <source>%1 units to the goal</source>
        <translation>距目标 %1 单位</translation>
    </message>
    <message>
        <source>No run open</source>
        <translation>未打开运行</translation>
    </message>
    <message>
        <source>Whole scene (M: close-up)</source>
        <translation>整个场景（M：特写）</translation>
    </message>
    <message>
        <source>Close-up (M: whole scene)</source>
        <translation>特写（M：整个场景）</translation>
    </message>
    <message>
        <source>Zoomed %1x (double click: whole scene)</source>
        <translation>缩放 %1 倍（双击：整个场景）</translation>
    </message>
    <message>
        <source>Close-up zoomed %1x (double click: close-up)</source>
        <translation>特写，缩放 %1 倍（双击：特写）</translation>
    </message>
    <message>
        <source>■ hole N: a gap N units wide that the model felt on one side</source>
        <translation>■ 空隙 N：模型在一侧感到的宽 N 单位的空隙</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListModel</name>
    <message>
        <source>%1
imported from %2</source>
        <translation>%1
导入自 %2</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Subject</source>
        <translation>受试者</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Labelled</source>
        <translation>已标注</translation>
    </message>
    <message>
        <source>to do</source>
        <translation>待办</translation>
    </message>
    <message>
        <source>labelled</source>
        <translation>已标注</translation>
    </message>
    <message>
        <source>reviewed</source>
        <translation>已审核</translation>
    </message>
    <message>
        <source>Assigned</source>
        <translation>分配</translation>
    </message>
    <message>
        <source>%1 % (model %2 %)</source>
        <translation>%1 %（模型 %2 %）</translation>
    </message>
    <message>
        <source>Steps x groups labelled in the current set: %1 % by people, %2 % by a model</source>
        <translation>当前集中已标注的步×组：人工 %1 %，模型 %2 %</translation>
    </message>
</context>
<context>
    <name>tactile::gui::RunListView</name>
    <message>
        <source>Filter runs by name, scene, subject or outcome</source>
        <translation>按名称、场景、受试者或结果筛选运行</translation>
    </message>
    <message>
        <source>Assigned to me</source>
        <translation>分配给我</translation>
    </message>
    <message>
        <source>Only the runs assigned to the annotator named in Preferences</source>
        <translation>仅显示分配给首选项中所填标注者的运行</translation>
    </message>
    <message>
        <source>Assign to...</source>
        <translation>分配给...</translation>
    </message>
    <message>
        <source>My Assignment: To Do</source>
        <translation>我的任务：待办</translation>
    </message>
    <message>
        <source>My Assignment: Labelled</source>
        <translation>我的任务：已标注</translation>
    </message>
    <message>
        <source>My Assignment: Reviewed</source>
        <translation>我的任务：已审核</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SignalBarsView</name>
    <message>
        <source>normal</source>
        <translation>法向力</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>剪切力</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimSession</name>
    <message>
        <source>An experiment run needs the subject&apos;s name.</source>
        <translation>实验运行需要受试者姓名。</translation>
    </message>
    <message>
        <source>A subject&apos;s name must be one line.</source>
        <translation>受试者姓名只能有一行。</translation>
    </message>
    <message>
        <source>Autonomous mode needs a driver.</source>
        <translation>自主模式需要一个驾驶程序。</translation>
    </message>
    <message>
        <source>The step length must be in (0, 1] seconds.</source>
        <translation>步长必须在 (0, 1] 秒之间。</translation>
    </message>
    <message>
        <source>The time limit must be positive.</source>
        <translation>时间限制必须为正数。</translation>
    </message>
    <message>
        <source>practice</source>
        <translation>练习</translation>
    </message>
    <message>
        <source>experiment</source>
        <translation>实验</translation>
    </message>
    <message>
        <source>autonomous</source>
        <translation>自主</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SimWindow</name>
    <message>
        <source>Run %1 ended: %2</source>
        <translation>运行 %1 已结束：%2</translation>
    </message>
    <message>
        <source>Tactile Simulator</source>
        <translation>触觉模拟器</translation>
    </message>
    <message>
        <source>Practice</source>
        <translation>练习</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>实验</translation>
    </message>
    <message>
        <source>Autonomous</source>
        <translation>自主</translation>
    </message>
    <message>
        <source>needed in experiment mode</source>
        <translation>实验模式下必填</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation> 步/秒</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Subject</source>
        <translation>受试者</translation>
    </message>
    <message>
        <source>Seed (start, goal)</source>
        <translation>随机种子（起点、目标）</translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation>时间限制</translation>
    </message>
    <message>
        <source>Step rate</source>
        <translation>步速</translation>
    </message>
    <message>
        <source>Navigator model</source>
        <translation>导航器模型</translation>
    </message>
    <message>
        <source>Start New Run</source>
        <translation>开始新运行</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>单步</translation>
    </message>
    <message>
        <source>Give Up</source>
        <translation>放弃</translation>
    </message>
    <message>
        <source>Data &gt;&gt;</source>
        <translation>数据 &gt;&gt;</translation>
    </message>
    <message>
        <source>Open in Workbench</source>
        <translation>在工作台中打开</translation>
    </message>
    <message>
        <source>Signal per group</source>
        <translation>各组信号</translation>
    </message>
    <message>
        <source>Experiment panel</source>
        <translation>实验面板</translation>
    </message>
    <message>
        <source>The run so far</source>
        <translation>目前的运行</translation>
    </message>
    <message>
        <source>Bug2 bumper (no model)</source>
        <translation>Bug2 保险杠（无模型）</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Built-in &amp;Scenes</source>
        <translation>内置场景(&amp;S)</translation>
    </message>
    <message>
        <source>Open Scene &amp;File...</source>
        <translation>打开场景文件(&amp;F)...</translation>
    </message>
    <message>
        <source>Open Run in &amp;Workbench</source>
        <translation>在工作台中打开运行(&amp;W)</translation>
    </message>
    <message>
        <source>Save Run as &amp;CSV...</source>
        <translation>将运行保存为 CSV(&amp;C)...</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>关闭(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>运行(&amp;R)</translation>
    </message>
    <message>
        <source>Start &amp;New Run</source>
        <translation>开始新运行(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Go / Pause (P)</source>
        <translation>开始 / 暂停（P）(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Step (N)</source>
        <translation>单步（N）(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Give Up</source>
        <translation>放弃(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>Robot Close-up / Whole Scene (M)</source>
        <translation>机器人特写 / 整个场景（M）</translation>
    </message>
    <message>
        <source>&amp;Data Panel</source>
        <translation>数据面板(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Briefing: Bug1 and Bug2</source>
        <translation>任务简介：Bug1 与 Bug2(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>按键(&amp;K)</translation>
    </message>
    <message>
        <source>Scene %1: press Start New Run</source>
        <translation>场景 %1：请点击“开始新运行”</translation>
    </message>
    <message>
        <source>Run %1 ready: drive with the arrow keys and W, A, S, D (Help &gt; Keys)</source>
        <translation>运行 %1 已就绪：用方向键和 W、A、S、D 驾驶（帮助 &gt; 按键）</translation>
    </message>
    <message>
        <source>(not stored)</source>
        <translation>（未保存）</translation>
    </message>
    <message>
        <source>The scene stays hidden in experiment mode</source>
        <translation>实验模式下场景保持隐藏</translation>
    </message>
    <message>
        <source>v %1 units/s   ω %2 rad/s</source>
        <translation>v %1 单位/秒   ω %2 rad/s</translation>
    </message>
    <message>
        <source>Blocked: the last step was stopped</source>
        <translation>受阻：上一步被阻挡</translation>
    </message>
    <message>
        <source>Moving freely</source>
        <translation>自由移动</translation>
    </message>
    <message>
        <source>No step yet</source>
        <translation>还没有步</translation>
    </message>
    <message>
        <source>No run yet.</source>
        <translation>还没有运行。</translation>
    </message>
    <message>
        <source>%1 mode, scene %2, step %3 (%4 s)</source>
        <translation>%1 模式，场景 %2，第 %3 步（%4 秒）</translation>
    </message>
    <message>
        <source>, %1 s left</source>
        <translation>，剩余 %1 秒</translation>
    </message>
    <message>
        <source>
run %1, %2 steps stored</source>
        <translation>
运行 %1，已保存 %2 步</translation>
    </message>
    <message>
        <source>
not stored (no database)</source>
        <translation>
未保存（无数据库）</translation>
    </message>
    <message>
        <source>
outcome: %1</source>
        <translation>
结果：%1</translation>
    </message>
    <message>
        <source>
paused: a drive key or Go starts the clock</source>
        <translation>
已暂停：按驾驶键或“开始”即开始计时</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Data &lt;&lt;</source>
        <translation>数据 &lt;&lt;</translation>
    </message>
    <message>
        <source>Open Scene</source>
        <translation>打开场景</translation>
    </message>
    <message>
        <source>Scenes (*.json);;All files (*)</source>
        <translation>场景 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>No steps recorded yet.</source>
        <translation>还没有记录任何步。</translation>
    </message>
    <message>
        <source>Save Run</source>
        <translation>保存运行</translation>
    </message>
    <message>
        <source>Run files (*.csv)</source>
        <translation>运行文件 (*.csv)</translation>
    </message>
    <message>
        <source>Briefing: Bug1 and Bug2</source>
        <translation>任务简介：Bug1 与 Bug2</translation>
    </message>
    <message>
        <source>&lt;p&gt;You drive the robot by touch: the close-up shows only the robot, which domes touch something, where it heads (blue) and where the goal lies (red), with the distance. Two classic strategies for a point robot that feels its way may help:&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug1&lt;/b&gt;&lt;br&gt;1. Head for the goal.&lt;br&gt;2. When you hit an obstacle, go all the way round it, keeping contact, and remember the point where you were closest to the goal.&lt;br&gt;3. Go back to that point, leave the obstacle there and head for the goal again.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug2&lt;/b&gt;&lt;br&gt;1. Head for the goal along the straight line from the start to the goal (the S-G line).&lt;br&gt;2. When an obstacle is in the way, follow its edge until you meet the S-G line again, closer to the goal than where you hit it.&lt;br&gt;3. Leave the obstacle there and go on along the line.&lt;/p&gt;&lt;p&gt;The robot is not a point: it is 140 long and 80 wide, it turns about its rear axle, and it loses contact easily when it follows an edge carelessly.&lt;/p&gt;</source>
        <translation>&lt;p&gt;您通过触觉驾驶机器人：特写只显示机器人本身、哪些触点正在接触物体、它的朝向（蓝色）以及目标所在方向（红色）和距离。对于靠摸索前进的点状机器人，有两种经典策略可供参考：&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug1&lt;/b&gt;&lt;br&gt;1. 朝目标前进。&lt;br&gt;2. 碰到障碍物时，保持接触绕它完整走一圈，并记住离目标最近的那个点。&lt;br&gt;3. 回到该点，在那里离开障碍物，再次朝目标前进。&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bug2&lt;/b&gt;&lt;br&gt;1. 沿起点到目标的直线（S-G 线）朝目标前进。&lt;br&gt;2. 遇到障碍物挡路时，沿其边缘行走，直到再次遇到 S-G 线，且该处比碰到障碍物的位置更接近目标。&lt;br&gt;3. 在那里离开障碍物，继续沿直线前进。&lt;/p&gt;&lt;p&gt;机器人不是一个点：它长 140、宽 80，绕后轴转向，沿边缘行走时稍不留神就会失去接触。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Simulator Keys</source>
        <translation>模拟器按键</translation>
    </message>
    <message>
        <source>Run %1 ready: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>运行 %1 已就绪：“播放”（P）让导航器驾驶，“单步”（N）走一步</translation>
    </message>
    <message>
        <source>
paused: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>
已暂停：“播放”（P）让导航器驾驶，“单步”（N）走一步</translation>
    </message>
    <message>
        <source>Plan drive (map of touches)</source>
        <translation>按规划行驶（触碰地图）</translation>
    </message>
    <message>
        <source>Thesis strategies (wall following)</source>
        <translation>论文策略（沿墙行驶）</translation>
    </message>
    <message>
        <source>How a navigator with a model drives: by a plan on a map of what it touched (the default, as tactile navigate), or by the thesis&apos;s strategies (tactile navigate --wall-follow). The Bug2 bumper baseline ignores it.</source>
        <translation>带模型的导航器如何行驶：按其触碰所得地图上的规划（默认，同 tactile navigate），或按论文的策略（tactile navigate --wall-follow）。Bug2 保险杠基线忽略此项。</translation>
    </message>
    <message>
        <source>Navigator drives by</source>
        <translation>导航器行驶方式</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan are drawn (T: off)</source>
        <translation>已显示导航器的触觉地图和路径规划（T：隐藏）</translation>
    </message>
    <message>
        <source>The navigator&apos;s touch map and plan are hidden (T: on)</source>
        <translation>已隐藏导航器的触觉地图和路径规划（T：显示）</translation>
    </message>
    <message>
        <source>Simulator truth (the ceiling, no model)</source>
        <translation>模拟器真值（上限，无模型）</translation>
    </message>
    <message>
        <source>0: the scene&apos;s own</source>
        <translation>0：场景自身的</translation>
    </message>
    <message>
        <source>Experiment mode: the seed of start and goal. Autonomous mode: the seed of the start, as in tactile navigate --seeds. 0: the scene&apos;s own start and goal (where the map benchmark starts).</source>
        <translation>实验模式：起点和目标的种子。自主模式：起点的种子，与 tactile navigate --seeds 相同。0：场景自身的起点和目标（地图基准测试的起点）。</translation>
    </message>
    <message>
        <source>Model %1 has no model for %2: the navigator reads those groups as no contact all run long.</source>
        <translation>模型 %1 没有 %2 的模型：导航器在整个运行中将这些组视为无接触。</translation>
    </message>
    <message>
        <source>Run %1 paused: Play (P) lets the navigator drive, Step (N) takes one step</source>
        <translation>运行 %1 已暂停：播放 (P) 让导航器驾驶，单步 (N) 前进一步</translation>
    </message>
    <message>
        <source>Run %1: the navigator drives; Pause (P) stops it</source>
        <translation>运行 %1：导航器正在驾驶；暂停 (P) 使其停止</translation>
    </message>
    <message>
        <source>Run %1: driving, the clock runs; Give Up ends the run</source>
        <translation>运行 %1：正在驾驶，计时进行中；放弃结束运行</translation>
    </message>
    <message>
        <source>Goal reached: run %1 succeeded in %2 s</source>
        <translation>已到达目标：运行 %1 在 %2 秒内成功</translation>
    </message>
</context>
<context>
    <name>tactile::gui::StatusPictureView</name>
    <message>
        <source>Choose a scene and a mode, then press Start.</source>
        <translation>选择场景和模式，然后点击“开始新运行”。</translation>
    </message>
    <message>
        <source>%1 units to the goal</source>
        <translation>距目标 %1 单位</translation>
    </message>
    <message>
        <source>Whole scene (M: robot close-up)</source>
        <translation>整个场景（M：机器人特写）</translation>
    </message>
    <message>
        <source>Robot close-up (M: whole scene)</source>
        <translation>机器人特写（M：整个场景）</translation>
    </message>
    <message>
        <source>Robot close-up (scene hidden)</source>
        <translation>机器人特写（场景隐藏）</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>已触碰</translation>
    </message>
    <message>
        <source>closed to the plan</source>
        <translation>规划不可通行</translation>
    </message>
    <message>
        <source>plan, odometry (T)</source>
        <translation>规划，里程计（T）</translation>
    </message>
</context>
<context>
    <name>tactile::gui::StepControlsView</name>
    <message>
        <source>Previous step (Left)</source>
        <translation>上一步（左方向键）</translation>
    </message>
    <message>
        <source>Current step</source>
        <translation>当前步</translation>
    </message>
    <message>
        <source>Next step (Right)</source>
        <translation>下一步（右方向键）</translation>
    </message>
    <message>
        <source>Scrub through the run</source>
        <translation>拖动浏览运行</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>播放或暂停（空格键）</translation>
    </message>
    <message>
        <source>Playing speed</source>
        <translation>播放速度</translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation>%1 步/秒</translation>
    </message>
    <message>
        <source>of %1 steps</source>
        <translation>共 %1 步</translation>
    </message>
    <message>
        <source>Steps are numbered from 0 to %1</source>
        <translation>步的编号从 0 到 %1</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepCellsModel</name>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>fitted</source>
        <translation>已拟合</translation>
    </message>
    <message>
        <source>no model: %1</source>
        <translation>无模型：%1</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>组</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Covariance</source>
        <translation>协方差</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>下限</translation>
    </message>
    <message>
        <source>Features</source>
        <translation>特征</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>随机种子</translation>
    </message>
    <message>
        <source>Fit ms</source>
        <translation>拟合 ms</translation>
    </message>
    <message>
        <source>Predict ms</source>
        <translation>预测 ms</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>迭代次数</translation>
    </message>
    <message>
        <source>Converged</source>
        <translation>已收敛</translation>
    </message>
    <message>
        <source>Accuracy %</source>
        <translation>准确率 %</translation>
    </message>
    <message>
        <source>Balanced %</source>
        <translation>平衡准确率 %</translation>
    </message>
    <message>
        <source>Macro-F1</source>
        <translation>宏 F1</translation>
    </message>
    <message>
        <source>Held-out loglik</source>
        <translation>留出集对数似然</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>%1: %2 test steps%3</source>
        <translation>%1：%2 个测试步%3</translation>
    </message>
    <message>
        <source> (too few)</source>
        <translation>（过少）</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 (rarest %2, too few)</source>
        <translation>%1（最少的类 %2，过少）</translation>
    </message>
    <message>
        <source>%1 (rarest %2)</source>
        <translation>%1（最少的类 %2）</translation>
    </message>
    <message>
        <source>Decision</source>
        <translation>决策</translation>
    </message>
    <message>
        <source>Test steps</source>
        <translation>测试步数</translation>
    </message>
    <message>
        <source>no test data</source>
        <translation>没有测试数据</translation>
    </message>
    <message>
        <source>%1 trees, depth %2, rate %3, weight %4</source>
        <translation>%1 棵树，深度 %2，学习率 %3，权重 %4</translation>
    </message>
    <message>
        <source>Trees</source>
        <translation>树</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepPlot</name>
    <message>
        <source>Export PNG...</source>
        <translation>导出 PNG...</translation>
    </message>
    <message>
        <source>Export PDF...</source>
        <translation>导出 PDF...</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>导出 PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>导出 PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 文件 (*.pdf)</translation>
    </message>
    <message>
        <source>Variance floor</source>
        <translation>方差下限</translation>
    </message>
    <message>
        <source>Model order</source>
        <translation>模型阶数</translation>
    </message>
    <message>
        <source>Error: 100 - balanced accuracy (%)</source>
        <translation>误差：100 − 平衡准确率 (%)</translation>
    </message>
    <message>
        <source>group %1</source>
        <translation>%1 组</translation>
    </message>
    <message>
        <source>Pareto front (%1)</source>
        <translation>帕累托前沿（%1）</translation>
    </message>
    <message>
        <source>No fitted cells yet.</source>
        <translation>还没有已拟合的单元。</translation>
    </message>
    <message>
        <source>No fitted cells scored on test rows.</source>
        <translation>没有在测试行上评分的已拟合单元。</translation>
    </message>
    <message>
        <source>%1
%2: %3
%4: %5%6</source>
        <translation>%1
%2：%3
%4：%5%6</translation>
    </message>
    <message>
        <source>
cell %1 (click to select)</source>
        <translation>
单元 %1（单击以选择）</translation>
    </message>
    <message>
        <source>Correct rate per class (%)</source>
        <translation>每类正确率 (%)</translation>
    </message>
    <message>
        <source>Fit + predict time</source>
        <translation>拟合 + 预测时间</translation>
    </message>
    <message>
        <source>group %1, boosted trees</source>
        <translation>组 %1，提升树</translation>
    </message>
    <message>
        <source>dots: Gaussian mixtures</source>
        <translation>圆点：高斯混合模型</translation>
    </message>
    <message>
        <source>squares: boosted trees</source>
        <translation>方块：提升树</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsView</name>
    <message>
        <source>No sweep</source>
        <translation>无扫描</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>所有组</translation>
    </message>
    <message>
        <source>Group:</source>
        <translation>组：</translation>
    </message>
    <message>
        <source>Confusion</source>
        <translation>混淆矩阵</translation>
    </message>
    <message>
        <source>Class rates</source>
        <translation>类别比率</translation>
    </message>
    <message>
        <source>Rate vs floor</source>
        <translation>比率与下限</translation>
    </message>
    <message>
        <source>Rate vs order</source>
        <translation>比率与阶数</translation>
    </message>
    <message>
        <source>Time vs error</source>
        <translation>时间与误差</translation>
    </message>
    <message>
        <source>Contact patterns</source>
        <translation>接触模式</translation>
    </message>
    <message>
        <source>(cancelled: the finished cells)</source>
        <translation>（已取消：仅已完成的单元）</translation>
    </message>
    <message>
        <source>No cells yet.</source>
        <translation>还没有单元。</translation>
    </message>
    <message>
        <source>Select a cell.</source>
        <translation>请选择一个单元。</translation>
    </message>
    <message>
        <source>Cell %1: %2</source>
        <translation>单元 %1：%2</translation>
    </message>
    <message>
        <source>This cell was not scored: the test runs have no labelled rows of its group.</source>
        <translation>此单元未评分：测试运行中没有其所属组的已标注行。</translation>
    </message>
    <message>
        <source>Confusion (counts)</source>
        <translation>混淆矩阵（计数）</translation>
    </message>
    <message>
        <source>Confusion (row percent)</source>
        <translation>混淆矩阵（行百分比）</translation>
    </message>
    <message>
        <source>No contact patterns were kept for this cell.</source>
        <translation>此单元未保留接触模式。</translation>
    </message>
    <message>
        <source>No cell is fitted yet.</source>
        <translation>还没有单元完成拟合。</translation>
    </message>
    <message>
        <source>Precision per class, one-vs-rest, % - each group&apos;s best cell</source>
        <translation>各类别精确率（一对其余），% – 每组的最佳单元</translation>
    </message>
    <message>
        <source>This cell could not be fitted: %1</source>
        <translation>此单元无法拟合：%1</translation>
    </message>
    <message>
        <source>Group %1, GMM %2, order %3, variance floor %4, %5 features, seed %6, %7 decision</source>
        <translation>%1 组，GMM %2，阶数 %3，方差下限 %4，%5 个特征，随机种子 %6，%7 决策</translation>
    </message>
    <message>
        <source>Group %1, %2, variance floor %3, %4 features, seed %5, %6 decision</source>
        <translation>%1 组，%2，方差下限 %3，%4 个特征，随机种子 %5，%6 决策</translation>
    </message>
    <message>
        <source>step: the per-step argmax; online: the forward filter (causal); offline: forward-backward over the whole contact. Cells that differ only in it share one fit.</source>
        <translation>step：逐步取最大后验；online：前向滤波（因果）；offline：对整个接触做前向-后向。只在此项上不同的单元共用一次拟合。</translation>
    </message>
    <message>
        <source>Decision:</source>
        <translation>决策：</translation>
    </message>
    <message>
        <source>All decisions</source>
        <translation>全部决策</translation>
    </message>
    <message>
        <source>Sweep %1: %2 cells stored, %3 fitted, %4 could not be fitted</source>
        <translation>扫描 %1：已存储 %2 个单元，%3 个已拟合，%4 个无法拟合</translation>
    </message>
    <message>
        <source>no model of it is stored (Store Model of Cell stores one)</source>
        <translation>尚未存储其模型（“存储单元模型”可存储一个）</translation>
    </message>
    <message>
        <source>stored models of its cells: %1</source>
        <translation>其单元已存储的模型：%1</translation>
    </message>
    <message>
        <source>Precision per class, one-vs-rest (of the steps predicted a class, the share that are it), % - this cell</source>
        <translation>每类精确率，一对其余（在预测为某类的步中，确为该类的比例），% - 此单元</translation>
    </message>
    <message>
        <source>Correct rate per class of this cell (of the steps of a class, the share predicted as it), %</source>
        <translation>此单元每类正确率（在某类的步中，被预测为该类的比例），%</translation>
    </message>
    <message>
        <source>Group %1, boosted trees: %2 trees, depth %3, rate %4, min child weight %5, %6 features, seed %7, %8 decision</source>
        <translation>组 %1，提升树：%2 棵树，深度 %3，学习率 %4，最小子节点权重 %5，%6 特征，种子 %7，%8 决策</translation>
    </message>
</context>
<context>
    <name>tactile::gui::SweepResultsWindow</name>
    <message>
        <source>Sweep</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Export Report...</source>
        <translation>导出报告...</translation>
    </message>
    <message>
        <source>Store Model of Cell</source>
        <translation>保存单元的模型</translation>
    </message>
    <message>
        <source>Store Model</source>
        <translation>保存模型</translation>
    </message>
    <message>
        <source>Export Model of Cell...</source>
        <translation>导出单元的模型...</translation>
    </message>
    <message>
        <source>Sweep %1: %2 (%3)</source>
        <translation>扫描 %1：%2（%3）</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>导出报告</translation>
    </message>
    <message>
        <source>HTML report (*.html);;Markdown report (*.md);;CSV tables (*.csv);;Text (*.txt)</source>
        <translation>HTML 报告 (*.html);;Markdown 报告 (*.md);;CSV 表格 (*.csv);;文本 (*.txt)</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
    <message>
        <source>Select a cell first.</source>
        <translation>请先选择一个单元。</translation>
    </message>
    <message>
        <source>That cell has no model: %1</source>
        <translation>该单元没有模型：%1</translation>
    </message>
    <message>
        <source>Training the cell&apos;s model...</source>
        <translation>正在训练该单元的模型...</translation>
    </message>
    <message>
        <source>Export Model</source>
        <translation>导出模型</translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation>模型文件 (*.json)</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>Model of Cell</source>
        <translation>单元的模型</translation>
    </message>
    <message>
        <source>No model was stored: %1</source>
        <translation>未保存模型：%1</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored.</source>
        <translation>模型“%1”已保存。</translation>
    </message>
    <message>
        <source>Name (empty: %1):</source>
        <translation>名称（留空：%1）：</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Close this window (%1)</source>
        <translation>关闭此窗口 (%1)</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Model written to %1 (not stored in the database).</source>
        <translation>模型已写入 %1（未存入数据库）。</translation>
    </message>
    <message>
        <source>The sweep&apos;s status cannot be read: %1</source>
        <translation>无法读取扫描的状态：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n 个单元</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 cells done, %3 running, %4 pending, %5 failed</source>
        <translation>%2 个单元中已完成 %1 个，运行中 %3 个，待处理 %4 个，失败 %5 个</translation>
    </message>
    <message>
        <source>; about %1 left</source>
        <translation>；约剩 %1</translation>
    </message>
    <message>
        <source>; waiting for workers (tactile sweep work)</source>
        <translation>；正在等待工作进程（tactile sweep work）</translation>
    </message>
    <message>
        <source>job %1 on %2: %3</source>
        <translation>任务 %1（%2）：%3</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TableView</name>
    <message>
        <source>Export CSV...</source>
        <translation>导出 CSV...</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>导出 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TimelineView</name>
    <message>
        <source>Step</source>
        <translation>步</translation>
    </message>
    <message>
        <source>heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <source>blocked</source>
        <translation>受阻</translation>
    </message>
    <message>
        <source>%1 truth</source>
        <translation>%1 真值</translation>
    </message>
    <message>
        <source>%1 model</source>
        <translation>%1 模型</translation>
    </message>
    <message>
        <source>%1 ≠ label</source>
        <translation>%1 ≠ 标签</translation>
    </message>
    <message>
        <source>holes</source>
        <translation>缺口</translation>
    </message>
    <message>
        <source>step %1, %2 side: hole %3 units wide between domes %4 and %5</source>
        <translation>第 %1 步，%2 侧：触点 %4 与 %5 之间有宽 %3 单位的缺口</translation>
    </message>
    <message>
        <source>step %1, %2: the model says %3 (%4 %)</source>
        <translation>第 %1 步，%2：模型判为%3（%4 %）</translation>
    </message>
    <message>
        <source>, the label %1</source>
        <translation>，标签为%1</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>法向力</translation>
    </message>
    <message>
        <source>Shear</source>
        <translation>剪切力</translation>
    </message>
    <message>
        <source>Magnitude</source>
        <translation>合力大小</translation>
    </message>
    <message>
        <source>turn left</source>
        <translation>左转</translation>
    </message>
    <message>
        <source>turn right</source>
        <translation>右转</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>前进</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>后退</translation>
    </message>
    <message>
        <source>blue: facing +x
red: facing −x</source>
        <translation>蓝色：朝向 +x
红色：朝向 −x</translation>
    </message>
    <message>
        <source>red: command
grey: blocked</source>
        <translation>红色：指令
灰色：受阻</translation>
    </message>
    <message>
        <source>normal</source>
        <translation>法向力</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>剪切力</translation>
    </message>
    <message>
        <source>magnitude</source>
        <translation>合力大小</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>第 %1 步</translation>
    </message>
    <message>
        <source>steps %1-%2 (largest)</source>
        <translation>第 %1–%2 步（最大值）</translation>
    </message>
    <message>
        <source>%1, sensor %2 (%3 %4): %5 %6</source>
        <translation>%1，传感器 %2（%3 %4）：%5 %6</translation>
    </message>
    <message>
        <source>step %1: heading %2° (%3)</source>
        <translation>第 %1 步：航向 %2°（%3）</translation>
    </message>
    <message>
        <source>blue: facing +x</source>
        <translation>蓝色：朝向 +x</translation>
    </message>
    <message>
        <source>red: facing −x</source>
        <translation>红色：朝向 −x</translation>
    </message>
    <message>
        <source>step %1: v %2, omega %3%4</source>
        <translation>第 %1 步：v %2，omega %3%4</translation>
    </message>
    <message>
        <source>, blocked</source>
        <translation>，受阻</translation>
    </message>
    <message>
        <source>%1 online</source>
        <translation>%1 在线</translation>
    </message>
    <message>
        <source>%1 offline</source>
        <translation>%1 离线</translation>
    </message>
    <message>
        <source>step %1, %2: the %3 decision is %4</source>
        <translation>第 %1 步，%2：%3判定为%4</translation>
    </message>
    <message>
        <source>online (causal)</source>
        <translation>在线（因果）</translation>
    </message>
    <message>
        <source>offline (whole contact)</source>
        <translation>离线（整个接触）</translation>
    </message>
</context>
<context>
    <name>tactile::gui::TrainingDialog</name>
    <message>
        <source>Train and sweep</source>
        <translation>训练与扫描</translation>
    </message>
    <message>
        <source>Label set:</source>
        <translation>标签集：</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步</translation>
    </message>
    <message>
        <source>Train</source>
        <translation>训练</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>测试</translation>
    </message>
    <message>
        <source>Runs:</source>
        <translation>运行：</translation>
    </message>
    <message>
        <source>Split:</source>
        <translation>划分：</translation>
    </message>
    <message>
        <source>Groups:</source>
        <translation>组：</translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation>高斯</translation>
    </message>
    <message>
        <source>GMM</source>
        <translation>GMM</translation>
    </message>
    <message>
        <source>Methods:</source>
        <translation>方法：</translation>
    </message>
    <message>
        <source>Model orders (components per class), comma-separated</source>
        <translation>模型阶数（每类的分量数），以逗号分隔</translation>
    </message>
    <message>
        <source>Orders:</source>
        <translation>阶数：</translation>
    </message>
    <message>
        <source>Covariance:</source>
        <translation>协方差：</translation>
    </message>
    <message>
        <source>Variance floors, comma-separated</source>
        <translation>方差下限，以逗号分隔</translation>
    </message>
    <message>
        <source>Variance floors:</source>
        <translation>方差下限：</translation>
    </message>
    <message>
        <source>Features:</source>
        <translation>特征：</translation>
    </message>
    <message>
        <source>Seeds:</source>
        <translation>随机种子：</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>all cores</source>
        <translation>所有核心</translation>
    </message>
    <message>
        <source>Threads:</source>
        <translation>线程：</translation>
    </message>
    <message>
        <source>each group&apos;s default settings</source>
        <translation>每组的默认设置</translation>
    </message>
    <message>
        <source>Train model with:</source>
        <translation>训练模型时使用：</translation>
    </message>
    <message>
        <source>Run sweep</source>
        <translation>运行扫描</translation>
    </message>
    <message>
        <source>Train model</source>
        <translation>训练模型</translation>
    </message>
    <message>
        <source>Train one model per group and store it in the database</source>
        <translation>为每组训练一个模型并保存到数据库</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Choose the runs and the grid, then run a sweep or train a model.</source>
        <translation>选择运行和参数网格，然后运行扫描或训练模型。</translation>
    </message>
    <message>
        <source>Orders</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>Variance floors</source>
        <translation>方差下限</translation>
    </message>
    <message>
        <source>Seeds</source>
        <translation>随机种子</translation>
    </message>
    <message numerus="yes">
        <source>Sweep of %n cell(s) started.</source>
        <translation>
            <numerusform>已开始 %n 个单元的扫描。</numerusform>
        </translation>
    </message>
    <message>
        <source>Training started.</source>
        <translation>训练已开始。</translation>
    </message>
    <message>
        <source>Cancelling: running fits stop after their current iteration...</source>
        <translation>正在取消：进行中的拟合将在当前迭代后停止...</translation>
    </message>
    <message>
        <source>%1 of %2 done, about %3 left</source>
        <translation>已完成 %1 / %2，约剩 %3</translation>
    </message>
    <message>
        <source>%1 of %2 done</source>
        <translation>已完成 %1 / %2</translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation>扫描失败：%1</translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 cancelled after %2 s; its %n finished cell(s) are stored.</source>
        <translation>
            <numerusform>扫描 %1 在 %2 秒后取消；已完成的 %n 个单元已保存。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 finished: %n cell(s) in %2 s.</source>
        <translation>
            <numerusform>扫描 %1 完成：%n 个单元，用时 %2 秒。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: skipped (%2)</source>
        <translation>%1：已跳过（%2）</translation>
    </message>
    <message>
        <source>Model &apos;%1&apos; stored (%2 s). %3</source>
        <translation>模型“%1”已保存（%2 秒）。%3</translation>
    </message>
    <message>
        <source>Training cancelled; nothing was stored.</source>
        <translation>训练已取消；未保存任何内容。</translation>
    </message>
    <message>
        <source>Training failed: %1</source>
        <translation>训练失败：%1</translation>
    </message>
    <message>
        <source>Plan:</source>
        <translation>计划：</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>组</translation>
    </message>
    <message>
        <source>Balanced accuracy %</source>
        <translation>平衡准确率 %</translation>
    </message>
    <message>
        <source>Accuracy %</source>
        <translation>准确率 %</translation>
    </message>
    <message>
        <source>Training samples</source>
        <translation>训练样本数</translation>
    </message>
    <message>
        <source>Test samples</source>
        <translation>测试样本数</translation>
    </message>
    <message>
        <source>Fit s</source>
        <translation>拟合 s</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s)</source>
        <translation>
            <numerusform>%n 个单元</numerusform>
        </translation>
    </message>
    <message>
        <source>; the time left shows once the first cells finish (no sweep is stored yet to estimate from)</source>
        <translation>；首批单元完成后将显示剩余时间（尚无已保存的扫描可供估算）</translation>
    </message>
    <message>
        <source>Ready.</source>
        <translation>就绪。</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>已跳过：%1</translation>
    </message>
    <message>
        <source>Decision modes: step = each step alone; online = HMM forward filter over the contact (causal, what a navigator may use); offline = forward-backward over the whole contact. A sweep scores every ticked mode (cells differing only here share one fit); Train model always scores all three and its models decide online by default</source>
        <translation>判定模式：step = 每步单独判定；online = 在接触过程中做 HMM 前向滤波（因果，导航器可用的方式）；offline = 对整个接触做前向-后向计算。扫描会为每个勾选的模式评分（仅在此处不同的单元共用一次拟合）；“训练模型”总是为三种模式都评分，其模型默认在线判定</translation>
    </message>
    <message>
        <source>Decisions:</source>
        <translation>判定：</translation>
    </message>
    <message>
        <source>%1 scored 0 on %2 test steps</source>
        <translation>%1 在 %2 个测试步上得分为 0</translation>
    </message>
    <message>
        <source>%1 had no test data</source>
        <translation>%1 没有测试数据</translation>
    </message>
    <message>
        <source>%1. Store the model anyway?</source>
        <translation>%1。仍然保存该模型吗？</translation>
    </message>
    <message>
        <source>Store the model?</source>
        <translation>保存模型？</translation>
    </message>
    <message>
        <source>The model was not stored (%1).</source>
        <translation>模型未保存（%1）。</translation>
    </message>
    <message>
        <source>%1: balanced accuracy %2 % (%3 test steps)</source>
        <translation>%1：平衡准确率 %2 %（%3 个测试步）</translation>
    </message>
    <message>
        <source>%1: no test data</source>
        <translation>%1：没有测试数据</translation>
    </message>
    <message>
        <source>no test data</source>
        <translation>没有测试数据</translation>
    </message>
    <message>
        <source>score on the test runs</source>
        <translation>在测试运行上评分</translation>
    </message>
    <message>
        <source>leave one scene out: each scene scored by models trained without it</source>
        <translation>留一场景：每个场景由不含该场景训练的模型评分</translation>
    </message>
    <message>
        <source>leave one run out (Train model only; a sweep cannot)</source>
        <translation>留一运行（仅限“训练模型”；扫描不支持）</translation>
    </message>
    <message>
        <source>by-run: the runs marked Test are scored (the command line&apos;s default); by-scene: each scene&apos;s runs (marked for training) are scored by models trained without that scene, no test runs; leave-one-run-out: each run scored by a model trained on the others (Train model only)</source>
        <translation>by-run：对标记为测试的运行评分（命令行的默认值）；by-scene：每个场景（标记为训练）的运行由不含该场景训练的模型评分，无测试运行；leave-one-run-out：每个运行由在其余运行上训练的模型评分（仅限“训练模型”）</translation>
    </message>
    <message>
        <source>each group&apos;s default</source>
        <translation>各组默认值</translation>
    </message>
    <message>
        <source>Evidence weight:</source>
        <translation>证据权重：</translation>
    </message>
    <message>
        <source>Leave Them Out</source>
        <translation>排除它们</translation>
    </message>
    <message>
        <source>Untick the groups the test runs cannot score</source>
        <translation>取消勾选测试运行无法评分的组</translation>
    </message>
    <message numerus="yes">
        <source>, about %1 on %n thread(s) (each cell&apos;s rows, order and covariance form, timed by %2 stored cells)</source>
        <translation>
            <numerusform>，约 %1，使用 %n 个线程（按每个单元的行数、阶数和协方差形式，依据 %2 个已存储单元计时）</numerusform>
        </translation>
    </message>
    <message>
        <source>the test runs hold no labelled contact steps of %1</source>
        <translation>测试运行中没有 %1 的已标注接触步</translation>
    </message>
    <message>
        <source>too few (under %1) of %2</source>
        <translation>%2 的步数太少（少于 %1）</translation>
    </message>
    <message>
        <source>Cannot be scored: %1. Their cells would be fitted but read &quot;no test data&quot;.</source>
        <translation>无法评分：%1。其单元会被拟合，但显示“无测试数据”。</translation>
    </message>
    <message>
        <source>Plan for workers</source>
        <translation>为工作进程规划</translation>
    </message>
    <message>
        <source>Store the sweep with every cell pending, to be filled by tactile sweep work processes on any machine that reaches the database, or by a Slurm job array</source>
        <translation>保存扫描并将所有单元设为待处理，由任何能访问数据库的机器上的 tactile sweep work 进程或 Slurm 作业数组来完成</translation>
    </message>
    <message>
        <source>Copy Commands</source>
        <translation>复制命令</translation>
    </message>
    <message>
        <source>The sweep was not planned: %1</source>
        <translation>扫描未规划：%1</translation>
    </message>
    <message>
        <source># One worker; start as many as you like, on any machine that reaches the database:</source>
        <translation># 一个工作进程；可在任何能访问数据库的机器上启动任意多个：</translation>
    </message>
    <message>
        <source># Or 4 workers as a Slurm job array:</source>
        <translation># 或者以 Slurm 作业数组启动 4 个工作进程：</translation>
    </message>
    <message numerus="yes">
        <source>Sweep %1 planned: %n cell(s), all pending, for the workers below.</source>
        <translation>
            <numerusform>扫描 %1 已规划：%n 个单元，全部待处理，由下方的工作进程完成。</numerusform>
        </translation>
    </message>
    <message>
        <source>Boosted trees</source>
        <translation>提升树</translation>
    </message>
    <message>
        <source>Gradient-boosted trees (XGBoost) under the same class chain: the online and offline decisions use their class posteriors divided by the priors</source>
        <translation>在同一类别链下的梯度提升树（XGBoost）：在线和离线决策使用其类别后验概率除以先验</translation>
    </message>
    <message>
        <source>Boosting rounds (trees per class), comma-separated</source>
        <translation>提升轮数（每类的树数），以逗号分隔</translation>
    </message>
    <message>
        <source>Largest tree depths, comma-separated</source>
        <translation>最大树深度，以逗号分隔</translation>
    </message>
    <message>
        <source>Learning rates (shrinkage of each round), comma-separated</source>
        <translation>学习率（每轮的收缩），以逗号分隔</translation>
    </message>
    <message>
        <source>Least summed weight in a leaf, comma-separated</source>
        <translation>叶节点的最小权重和，以逗号分隔</translation>
    </message>
    <message>
        <source>rounds</source>
        <translation>轮数</translation>
    </message>
    <message>
        <source>depth</source>
        <translation>深度</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>学习率</translation>
    </message>
    <message>
        <source>min weight</source>
        <translation>最小权重</translation>
    </message>
    <message>
        <source>Trees:</source>
        <translation>树：</translation>
    </message>
    <message>
        <source>Trees</source>
        <translation>树</translation>
    </message>
    <message>
        <source>Depths</source>
        <translation>深度</translation>
    </message>
    <message>
        <source>Learning rates</source>
        <translation>学习率</translation>
    </message>
    <message>
        <source>Min child weights</source>
        <translation>最小子节点权重</translation>
    </message>
    <message>
        <source>Train model uses each group&apos;s default family with its settings (order, covariance and floor, or rounds and depth), features and evidence weight, as tactile train does; unticked, the first value of every list above</source>
        <translation>“训练模型”与 tactile train 一样，使用每组的默认模型族及其设置（阶数、协方差和下限，或轮数和深度）、特征和证据权重；不勾选时使用上面每个列表的第一个值</translation>
    </message>
    <message>
        <source>Train model: the weight of each step&apos;s evidence in the online and offline decisions (1 is the plain HMM; smaller lets the class chain outweigh single steps, larger lets a few steps outweigh the chain), as tactile train --emission-weight. Sweeps always use each group&apos;s default for the method</source>
        <translation>训练模型：每一步证据在在线和离线决策中的权重（1 为普通 HMM；较小时类别链可压过单步，较大时几步证据可压过类别链），同 tactile train --emission-weight。扫描始终使用每组对该方法的默认值</translation>
    </message>
</context>
<context>
    <name>tactile::gui::UserGuideWindow</name>
    <message>
        <source>User Guide</source>
        <translation>用户指南</translation>
    </message>
    <message>
        <source>User Guide: %1</source>
        <translation>用户指南：%1</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>后退</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>前进</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>目录</translation>
    </message>
    <message>
        <source>%1 is not part of the embedded guide; it is in the source tree.</source>
        <translation>%1 不属于内嵌指南；它在源代码树中。</translation>
    </message>
</context>
</TS>
