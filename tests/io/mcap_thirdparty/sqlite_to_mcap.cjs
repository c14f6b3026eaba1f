// Converts a rosbag2 sqlite3 bag (.db3) to MCAP with third-party code only: sql.js (SQLite
// compiled to WebAssembly) reads tables topics and messages, @mcap/core's McapWriter writes the
// MCAP file (profile "ros2", one schema per type with encoding "ros2msg", channels with message
// encoding "cdr", messages in timestamp order), with zstd chunks from @foxglove/wasm-zstd or
// uncompressed chunks. Used by mcap_thirdparty_test.sh to check tessera's MCAP reader against an
// independent writer. Usage: node sqlite_to_mcap.cjs IN.db3 OUT.mcap zstd|none
"use strict";
const fs = require("fs");
const { McapWriter } = require("@mcap/core");
const initSqlJs = require("sql.js");
const zstd = require("@foxglove/wasm-zstd");

class FileWritable {
  constructor(path) {
    this.fd = fs.openSync(path, "w");
    this.pos = 0n;
  }
  async write(buffer) {
    fs.writeSync(this.fd, buffer);
    this.pos += BigInt(buffer.byteLength);
  }
  position() {
    return this.pos;
  }
  close() {
    fs.closeSync(this.fd);
  }
}

async function main() {
  const [input, output, compression] = process.argv.slice(2);
  if (!input || !output || !["zstd", "none"].includes(compression)) {
    console.error("usage: node sqlite_to_mcap.cjs IN.db3 OUT.mcap zstd|none");
    process.exit(2);
  }
  await zstd.isLoaded;
  const SQL = await initSqlJs();
  const db = new SQL.Database(fs.readFileSync(input));
  const writable = new FileWritable(output);
  const writer = new McapWriter({
    writable,
    chunkSize: 256 * 1024,
    compressChunk:
      compression === "zstd"
        ? (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) })
        : undefined,
  });
  await writer.start({ profile: "ros2", library: "@mcap/core via tessera's test" });
  const channels = new Map();
  const schemas = new Map();
  const topics = db.exec("SELECT id, name, type FROM topics ORDER BY id")[0].values;
  for (const [id, name, type] of topics) {
    if (!schemas.has(type)) {
      schemas.set(
        type,
        await writer.registerSchema({ name: type, encoding: "ros2msg", data: new Uint8Array() }),
      );
    }
    channels.set(
      id,
      await writer.registerChannel({
        topic: name,
        schemaId: schemas.get(type),
        messageEncoding: "cdr",
        metadata: new Map(),
      }),
    );
  }
  const stmt = db.prepare("SELECT topic_id, timestamp, data FROM messages ORDER BY timestamp, id");
  let sequence = 0;
  let count = 0;
  while (stmt.step()) {
    const [topicId, timestamp, data] = stmt.get(null, { useBigInt: true });
    await writer.addMessage({
      channelId: channels.get(Number(topicId)),
      sequence: sequence++,
      logTime: BigInt(timestamp),
      publishTime: BigInt(timestamp),
      data,
    });
    ++count;
  }
  stmt.free();
  await writer.end();
  writable.close();
  console.log(`${output}: ${count} messages on ${topics.length} topics (${compression} chunks)`);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
