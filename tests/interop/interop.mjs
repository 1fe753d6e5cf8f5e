// Interoperability with the MCAP format's reference implementation (@mcap/core, @mcap/support)
// and Foxglove's ROS 2 message tools (@foxglove/rosmsg, @foxglove/rosmsg2-serialization,
// @foxglove/rosmsg-msgs-common).
//
//   node interop.mjs write-bags DIR [STEPS]
//       Writes ROS 2 bags as a robot's recorder would: Twist on /cmd_vel, Odometry on /odom and
//       Float32MultiArray (88 values, normals then shears) on /tactile at jittered stamps, zstd
//       and uncompressed, with DIR/expected.json holding every value a step must import as.
//   node interop.mjs check-import EXPECTED.json RUN.csv
//       Compares a run file exported after `tactile import BAG --mapping` with the bag's values.
//   node interop.mjs check-export FILE.mcap RUN.csv
//       Reads one of tactile's exports with the reference reader (through its summary and chunk
//       indexes) and checks schemas, channels, message counts, statistics, chunk index and the
//       values against the run file it was exported from.
import fs from "node:fs";
import path from "node:path";
import { McapWriter, McapIndexedReader, McapStreamReader, TempBuffer } from "@mcap/core";
import { loadDecompressHandlers } from "@mcap/support";
import { parse, stringify } from "@foxglove/rosmsg";
import { MessageWriter } from "@foxglove/rosmsg2-serialization";
import { ros2jazzy } from "@foxglove/rosmsg-msgs-common";
import zstd from "@foxglove/wasm-zstd";

function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}
function check(condition, message) {
  if (!condition) fail(message);
}

// A type's ros2msg schema text: its definition, then each dependency after a MSG: line.
function schemaText(type) {
  const seen = new Set();
  const order = [];
  const visit = (name) => {
    if (seen.has(name)) return;
    seen.add(name);
    const def = ros2jazzy[name];
    check(def !== undefined, `no definition of ${name}`);
    order.push(def);
    for (const field of def.definitions) {
      if (field.isComplex === true && field.isConstant !== true) visit(field.type);
    }
  };
  visit(type);
  return stringify(order);
}

let STEPS = 240;
const SCALE = 1000; // metres in the bag, millimetres (scene units) in the run

async function writeBags(dir) {
  await zstd.isLoaded;
  fs.mkdirSync(dir, { recursive: true });
  const types = {
    "/tactile": "std_msgs/Float32MultiArray",
    "/odom": "nav_msgs/Odometry",
    "/cmd_vel": "geometry_msgs/Twist",
  };
  const texts = {};
  const writers = {};
  for (const [topic, type] of Object.entries(types)) {
    texts[topic] = schemaText(type);
    // The writer works from the text, as a reader of the bag will.
    writers[topic] = new MessageWriter(parse(texts[topic], { ros2: true }));
  }
  // One recording, two files: zstd chunks and uncompressed chunks.
  let seed = 12345;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  const steps = [];
  let t = 1_700_000_000_000_000_000n;
  for (let k = 0; k < STEPS; k++) {
    t += 20_000_000n + BigInt(Math.floor((random() - 0.5) * 4_000_000)); // 20 ms +- 2 ms
    const yaw = -3 + 6 * random();
    const values = [];
    for (let i = 0; i < 44; i++) values.push(random() < 0.7 ? 0 : Math.fround(5 * random()));
    for (let i = 0; i < 44; i++) values.push(values[i] === 0 ? 0 : Math.fround(10 * random() - 5));
    steps.push({
      t,
      odomT: t - 3_000_000n, // odometry and command arrive a little before the reading
      x: 2 * random(),
      y: 1 + random(),
      yaw,
      v: random() * 0.3,
      w: random() - 0.5,
      values,
    });
  }
  const expected = { steps: [], dtSeconds: 0 };
  for (const s of steps) {
    expected.steps.push({
      n: s.values.slice(0, 44),
      s: s.values.slice(44),
      x: s.x * SCALE,
      y: s.y * SCALE,
      theta: s.yaw,
      v: s.v * SCALE,
      omega: s.w,
    });
  }
  const periods = [];
  for (let k = 1; k < steps.length; k++) periods.push(Number(steps[k].t - steps[k - 1].t));
  periods.sort((a, b) => a - b);
  const mid = periods.length / 2;
  expected.dtSeconds =
    periods.length % 2 === 1 ? periods[Math.floor(mid)] * 1e-9 : 0.5 * (periods[mid - 1] + periods[mid]) * 1e-9;

  for (const compression of ["zstd", ""]) {
    const buffer = new TempBuffer();
    const writer = new McapWriter({
      writable: buffer,
      chunkSize: 16 * 1024,
      compressChunk:
        compression === "zstd"
          ? (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) })
          : undefined,
    });
    await writer.start({ profile: "ros2", library: "interop test" });
    const channels = {};
    for (const [topic, type] of Object.entries(types)) {
      const schemaId = await writer.registerSchema({
        name: type.replace("/", "/msg/"),
        encoding: "ros2msg",
        data: new TextEncoder().encode(texts[topic]),
      });
      channels[topic] = await writer.registerChannel({
        schemaId,
        topic,
        messageEncoding: "cdr",
        metadata: new Map([["offered_qos_profiles", ""]]),
      });
    }
    let sequence = 0;
    const add = async (topic, time, message) => {
      await writer.addMessage({
        channelId: channels[topic],
        sequence: sequence++,
        logTime: time,
        publishTime: time,
        data: writers[topic].writeMessage(message),
      });
    };
    const stamp = (time) => ({ sec: Number(time / 1_000_000_000n), nanosec: Number(time % 1_000_000_000n) });
    for (const s of steps) {
      const pose = {
        position: { x: s.x, y: s.y, z: 0 },
        orientation: { x: 0, y: 0, z: Math.sin(s.yaw / 2), w: Math.cos(s.yaw / 2) },
      };
      await add("/odom", s.odomT, {
        header: { stamp: stamp(s.odomT), frame_id: "odom" },
        child_frame_id: "base_link",
        pose: { pose, covariance: new Array(36).fill(0.01) },
        twist: { twist: { linear: { x: s.v, y: 0, z: 0 }, angular: { x: 0, y: 0, z: s.w } }, covariance: new Array(36).fill(0) },
      });
      await add("/cmd_vel", s.odomT, { linear: { x: s.v, y: 0, z: 0 }, angular: { x: 0, y: 0, z: s.w } });
      await add("/tactile", s.t, {
        layout: { dim: [{ label: "domes", size: 88, stride: 88 }], data_offset: 0 },
        data: new Float32Array(s.values),
      });
    }
    await writer.end();
    const name = compression === "zstd" ? "bag_zstd.mcap" : "bag_none.mcap";
    fs.writeFileSync(path.join(dir, name), buffer.get());
  }
  fs.writeFileSync(path.join(dir, "expected.json"), JSON.stringify(expected));
  fs.writeFileSync(
    path.join(dir, "mapping.json"),
    JSON.stringify({
      tactile: { topic: "/tactile", layout: "normal-then-shear" },
      pose: { topic: "/odom" },
      command: { topic: "/cmd_vel" },
      scale: SCALE,
    }),
  );
  console.log(`wrote ${STEPS}-step bags in ${dir}`);
}

// A run file: metadata and rows by column name.
function readRunCsv(file) {
  const lines = fs.readFileSync(file, "utf8").split("\n").filter((l) => l.length > 0);
  const meta = {};
  let i = 0;
  for (; lines[i].startsWith("#"); i++) {
    const m = /^#\s*([^:]+):\s*(.*)$/.exec(lines[i]);
    meta[m[1].trim()] = m[2].trim();
  }
  const header = lines[i].split(",");
  const rows = lines.slice(i + 1).map((line) => {
    const fields = line.split(",");
    const row = {};
    header.forEach((h, j) => (row[h] = fields[j]));
    return row;
  });
  return { meta, header, rows };
}

function checkImport(expectedFile, csvFile) {
  const expected = JSON.parse(fs.readFileSync(expectedFile, "utf8"));
  const run = readRunCsv(csvFile);
  check(run.rows.length === expected.steps.length, `${run.rows.length} steps, expected ${expected.steps.length}`);
  check(Number(run.meta.dt) === expected.dtSeconds, `dt ${run.meta.dt}, expected ${expected.dtSeconds}`);
  expected.steps.forEach((e, k) => {
    const row = run.rows[k];
    for (let i = 0; i < 44; i++) {
      check(Number(row[`n${i}`]) === e.n[i], `step ${k} n${i}: ${row[`n${i}`]}, expected ${e.n[i]}`);
      check(Number(row[`s${i}`]) === e.s[i], `step ${k} s${i}: ${row[`s${i}`]}, expected ${e.s[i]}`);
    }
    check(Number(row.x) === e.x, `step ${k} x: ${row.x}, expected ${e.x}`);
    check(Number(row.y) === e.y, `step ${k} y: ${row.y}, expected ${e.y}`);
    check(Math.abs(Number(row.theta) - e.theta) < 1e-12, `step ${k} theta: ${row.theta}, expected ${e.theta}`);
    check(Number(row.v) === e.v, `step ${k} v: ${row.v}, expected ${e.v}`);
    check(Number(row.omega) === e.omega, `step ${k} omega: ${row.omega}, expected ${e.omega}`);
    check(row.blocked === "0", `step ${k} blocked ${row.blocked}`);
  });
  console.log(`import of ${path.basename(csvFile)}: ${run.rows.length} steps match value for value`);
}

async function checkExport(mcapFile, csvFile) {
  const run = readRunCsv(csvFile);
  const steps = run.rows.length;
  const bytes = fs.readFileSync(mcapFile);
  const decompressHandlers = await loadDecompressHandlers();
  const reader = await McapIndexedReader.Initialize({ readable: new TempBuffer(bytes), decompressHandlers });
  // Statistics and chunk indexes, as a viewer uses them to seek.
  const stats = reader.statistics;
  check(stats !== undefined, "no Statistics record");
  check(reader.chunkIndexes.length === stats.chunkCount && stats.chunkCount > 0, "chunk indexes and statistics disagree");
  for (const c of reader.chunkIndexes) {
    check(c.compression === "zstd", `a chunk compressed with '${c.compression}'`);
    check(c.messageIndexOffsets.size > 0, "a chunk without message indexes");
  }
  const topics = new Map([...reader.channelsById.values()].map((c) => [c.topic, c]));
  const expectTopic = (topic, schemaName, count) => {
    const channel = topics.get(topic);
    check(channel !== undefined, `no channel ${topic}`);
    check(channel.messageEncoding === "json", `${topic}: encoding ${channel.messageEncoding}`);
    const schema = reader.schemasById.get(channel.schemaId);
    check(schema.name === schemaName && schema.encoding === "jsonschema", `${topic}: schema ${schema.name} ${schema.encoding}`);
    JSON.parse(new TextDecoder().decode(schema.data)); // a JSON Schema is JSON
    const counted = stats.channelMessageCounts.get(channel.id);
    check(counted === BigInt(count), `${topic}: ${counted} messages in the statistics, expected ${count}`);
  };
  expectTopic("/tactile", "tactile.TactileReadings", steps);
  expectTopic("/robot/state", "tactile.RobotState", steps);
  expectTopic("/robot/pose", "foxglove.PoseInFrame", steps);
  if (topics.has("/truth")) expectTopic("/truth", "tactile.Classes", steps);
  if (topics.has("/scene")) expectTopic("/scene", "foxglove.SceneUpdate", 1);

  // Every message through the index, in log-time order, with CRCs checked; values against the CSV.
  const dtNs = BigInt(Math.round(Number(run.meta.dt) * 1e9));
  let count = 0n;
  let last = -1n;
  const tactileId = topics.get("/tactile").id;
  const stateId = topics.get("/robot/state").id;
  for await (const m of reader.readMessages({ validateCrcs: true })) {
    count++;
    check(m.logTime >= last, "messages out of log-time order");
    last = m.logTime;
    if (m.channelId === tactileId || m.channelId === stateId) {
      const msg = JSON.parse(new TextDecoder().decode(m.data));
      const row = run.rows[msg.step];
      check(m.logTime === BigInt(Math.round(msg.step * Number(run.meta.dt) * 1e9)) || dtNs === 0n, `step ${msg.step} at ${m.logTime}`);
      if (m.channelId === stateId) {
        for (const key of ["x", "y", "theta", "v", "omega"]) {
          check(msg[key] === Number(row[key]), `step ${msg.step} ${key}: ${msg[key]} vs ${row[key]}`);
        }
      } else {
        check(msg.F.n.length === 8 && msg.FLC.n.length === 2 && msg.L.s.length === 10, "groups");
        check(msg.F.n[0] === Number(row.n0) && msg.FRC.s[1] === Number(row.s43), `step ${msg.step} domes`);
      }
    }
  }
  check(count === stats.messageCount, `${count} messages read, statistics say ${stats.messageCount}`);
  // The stream reader (no index) sees the same file, metadata included.
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(bytes);
  let streamed = 0n;
  let metadata = 0;
  for (let record; (record = stream.nextRecord()); ) {
    if (record.type === "Message") streamed++;
    if (record.type === "Metadata" && record.name === "tactile.run") {
      metadata++;
      check(record.metadata.get("format") === "tactile-run 1", "tactile.run metadata");
    }
  }
  check(stream.done(), "the stream reader did not reach the end");
  check(streamed === count && metadata === 1, `stream reader: ${streamed} messages, ${metadata} metadata`);
  console.log(`export ${path.basename(mcapFile)}: ${count} messages, ${stats.chunkCount} chunks read by the reference reader`);
}

const [command, a, b] = process.argv.slice(2);
if (command === "write-bags") {
  if (b !== undefined) STEPS = Number(b); // a bigger recording, for benchmarks
  await writeBags(a);
}
else if (command === "check-import") checkImport(a, b);
else if (command === "check-export") await checkExport(a, b);
else fail(`unknown command ${command}`);
