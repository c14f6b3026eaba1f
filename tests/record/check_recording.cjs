// Third-party check of a tessera MCAP recording (--record) with readers we did not write:
// @mcap/core's indexed reader (summary, chunk indexes, chunk CRCs, seek by time),
// @foxglove/rosmsg's ros2msg parser and @foxglove/rosmsg2-serialization's CDR reader (every
// message decodes against the schema in the file with no bytes left over), @foxglove/crc (the
// data section CRC). Usage: node check_recording.cjs FILE.mcap TOPIC... (topics that must be there)
// Prints one summary line; exits 1 with the reason on the first problem.
"use strict";
const fs = require("fs");
const { McapIndexedReader } = require("@mcap/core");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");
const { crc32 } = require("@foxglove/crc");
const zstd = require("@foxglove/wasm-zstd");

function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

function check(condition, message) {
  if (!condition) fail(message);
}

// Field checks per type: what a viewer relies on.
const fieldChecks = {
  "nav_msgs/msg/OccupancyGrid": (m) =>
    m.info.width * m.info.height === m.data.length && m.info.resolution > 0 && m.data.length > 0,
  "tf2_msgs/msg/TFMessage": (m) =>
    m.transforms.length > 0 && m.transforms.every((t) => t.child_frame_id && t.header.frame_id),
  "sensor_msgs/msg/LaserScan": (m) => m.ranges.length > 0 && m.angle_increment !== 0,
  "nav_msgs/msg/Odometry": (m) => m.child_frame_id.length > 0,
  "nav_msgs/msg/Path": (m) => m.poses.length > 0,
  "visualization_msgs/msg/MarkerArray": (m) => m.markers.length > 0,
};

async function main() {
  const [file, ...expected] = process.argv.slice(2);
  if (!file) fail("usage: node check_recording.cjs FILE.mcap TOPIC...");
  const bytes = fs.readFileSync(file);
  await zstd.isLoaded;
  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  };
  const reader = await McapIndexedReader.Initialize({
    readable,
    decompressHandlers: { zstd: (data, size) => zstd.decompress(data, Number(size)) },
  });

  check(reader.header.profile === "ros2", `profile '${reader.header.profile}', expected ros2`);
  check(reader.statistics !== undefined, "no statistics record in the summary");
  check(reader.chunkIndexes.length > 0, "no chunk index in the summary");
  for (const [opcode, name] of [[3, "schema"], [4, "channel"], [0x0b, "statistics"], [8, "chunk index"]]) {
    check(reader.summaryOffsetsByOpcode.has(opcode), `no summary offset for the ${name} group`);
  }
  check(reader.chunkIndexes.every((c) => c.compression === "zstd"), "a chunk is not zstd");
  check(reader.dataSectionCrc !== undefined && reader.dataSectionCrc !== 0, "no data section CRC");
  const dataCrc = crc32(bytes.subarray(0, Number(reader.dataEndOffset)));
  check(dataCrc === reader.dataSectionCrc,
        `data section CRC ${dataCrc}, the file says ${reader.dataSectionCrc}`);

  const readers = new Map();  // schema id -> MessageReader
  const counts = new Map();   // topic -> messages
  const times = [];
  for await (const message of reader.readMessages()) {
    const channel = reader.channelsById.get(message.channelId);
    check(channel !== undefined, `message on unknown channel ${message.channelId}`);
    check(channel.messageEncoding === "cdr", `${channel.topic}: encoding ${channel.messageEncoding}`);
    const schema = reader.schemasById.get(channel.schemaId);
    check(schema !== undefined && schema.encoding === "ros2msg", `${channel.topic}: no ros2msg schema`);
    if (!readers.has(schema.id)) {
      const text = new TextDecoder().decode(schema.data);
      readers.set(schema.id, new MessageReader(parse(text, { ros2: true })));
    }
    const messageReader = readers.get(schema.id);
    let decoded;
    try {
      decoded = messageReader.readMessage(message.data);
    } catch (e) {
      fail(`${channel.topic} (${schema.name}) at ${message.logTime}: ${e.message}`);
    }
    check(!messageReader.lastReadHadTrailingBytes(),
          `${channel.topic} (${schema.name}): bytes left after decoding against the schema`);
    const fields = fieldChecks[schema.name];
    check(fields !== undefined, `${channel.topic}: unexpected type ${schema.name}`);
    check(fields(decoded), `${channel.topic}: fields of ${schema.name} do not hold together`);
    counts.set(channel.topic, (counts.get(channel.topic) ?? 0) + 1);
    times.push(message.logTime);
  }
  const total = times.length;
  check(BigInt(total) === reader.statistics.messageCount,
        `read ${total} messages, statistics say ${reader.statistics.messageCount}`);
  for (const [id, count] of reader.statistics.channelMessageCounts) {
    const topic = reader.channelsById.get(id).topic;
    check(BigInt(counts.get(topic) ?? 0) === count, `${topic}: statistics count ${count}`);
  }
  for (const topic of expected) check(counts.has(topic), `no message on ${topic}`);

  // Seek by time, through the chunk indexes: from just after the start of the last chunk on.
  // tessera writes in time order (neighbouring chunks may share their boundary stamp), so with
  // two chunks or more the seek must skip at least one.
  const seekTo = reader.chunkIndexes.reduce(
      (t, c) => (c.messageStartTime > t ? c.messageStartTime : t), 0n) + 1n;
  let fromSeek = 0;
  for await (const message of reader.readMessages({ startTime: seekTo })) {
    check(message.logTime >= seekTo, `seek to ${seekTo} returned a message at ${message.logTime}`);
    ++fromSeek;
  }
  const expectedFromSeek = times.filter((t) => t >= seekTo).length;
  check(fromSeek === expectedFromSeek,
        `seek to ${seekTo} returned ${fromSeek} messages, expected ${expectedFromSeek}`);
  const skipped = reader.chunkIndexes.filter((c) => c.messageEndTime < seekTo).length;
  check(reader.chunkIndexes.length < 2 || skipped > 0,
        `seek to ${seekTo} skips no chunk of ${reader.chunkIndexes.length}`);

  const topics = [...counts.entries()].map(([t, n]) => `${t} ${n}`).join(", ");
  console.log(`${file}: ${total} messages (${topics}); ${reader.chunkIndexes.length} chunks, ` +
              `seek into the last chunk skips ${skipped}`);
}

main().catch((e) => fail(e.stack ?? String(e)));
