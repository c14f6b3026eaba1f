// Issue 14's wire compatibility, the half done by an implementation we did not write: npm's
// @foxglove/rosmsg (the ros2msg parser) and @foxglove/rosmsg2-serialization (CDR reader and
// writer). For every <pkg>__<Type>.cdr in DIR (bytes tessera put on DDS, captured by
// `net_wire_tool capture`):
//   - parses <pkg>__<Type>.msg (the ROS 2 definition) and decodes the bytes with MessageReader; the
//     reader must consume the whole message (all but Cyclone's padding, whose size is in the low 2
//     bits of encapsulation byte 3), and the result must equal <pkg>__<Type>.json field for field,
//     walked along the definition: integers, strings and bools exactly, float32/float64 within 1e-6
//     relative, uint64/int64 as BigInt, arrays (TypedArrays) element for element;
//   - encodes the .json with MessageWriter and writes <pkg>__<Type>.foxglove.cdr for
//     `net_wire_tool check` to decode with tessera.
// Usage: node wire_check.cjs DIR. Prints "ok <pkg>/msg/<Type>" per type, "FAIL <type>: <field>:
// <what>" for each mismatch (the first differing field of the type), and exits 1 on any.
"use strict";
const fs = require("fs");
const path = require("path");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader, MessageWriter } = require("@foxglove/rosmsg2-serialization");

const kRelativeTolerance = 1e-6;
const kFloatTypes = new Set(["float32", "float64"]);
const kBigIntTypes = new Set(["int64", "uint64"]);

function show(v) {
  if (typeof v === "bigint") return `${v}n`;
  if (ArrayBuffer.isView(v)) return show(Array.from(v));
  if (Array.isArray(v)) return `[${v.map(show).join(", ")}]`;
  if (v !== null && typeof v === "object") {
    return `{${Object.entries(v).map(([k, x]) => `${k}: ${show(x)}`).join(", ")}}`;
  }
  return JSON.stringify(v);
}

class Mismatch extends Error {
  constructor(where, what) {
    super(`${where || "(message)"}: ${what}`);
  }
}

function join(where, name) {
  return where ? `${where}.${name}` : name;
}

// The parsed definitions by type name ("" for the root), as MessageReader looks them up.
function definitionsByName(defs) {
  return new Map(defs.map((d) => [d.name ?? "", d.definitions]));
}

// Throws a Mismatch at the first field where `actual` (foxglove's) differs from `expected` (the
// .json), one scalar of type `type`.
function compareScalar(types, type, expected, actual, where) {
  if (types.has(type)) {
    compareMessage(types, types.get(type), expected, actual, where);
  } else if (type === "time" || type === "duration") {
    compareMessage(types, [{ name: "sec", type: "int32" }, { name: "nanosec", type: "uint32" }],
                   expected, actual, where);
  } else if (kFloatTypes.has(type)) {
    if (typeof expected !== "number" || typeof actual !== "number") {
      throw new Mismatch(where, `expected ${show(expected)}, got ${show(actual)}`);
    }
    const tolerance = kRelativeTolerance * Math.max(Math.abs(expected), Math.abs(actual));
    if (!(expected === actual || Math.abs(expected - actual) <= tolerance)) {
      throw new Mismatch(where, `expected ${show(expected)}, got ${show(actual)} (${type})`);
    }
  } else if (kBigIntTypes.has(type)) {
    if (!Number.isSafeInteger(expected)) {
      throw new Mismatch(where, `the .json's ${show(expected)} is not a safe integer`);
    }
    if (typeof actual !== "bigint" || BigInt(expected) !== actual) {
      throw new Mismatch(where,
                         `expected ${show(BigInt(expected))}, got ${show(actual)} (${type})`);
    }
  } else if (expected !== actual) {
    throw new Mismatch(where, `expected ${show(expected)}, got ${show(actual)} (${type})`);
  }
}

function compareMessage(types, fields, expected, actual, where) {
  if (expected === null || typeof expected !== "object" || Array.isArray(expected)) {
    throw new Mismatch(where, `the .json has ${show(expected)}, not a message`);
  }
  if (actual === null || typeof actual !== "object") {
    throw new Mismatch(where, `expected a message, got ${show(actual)}`);
  }
  const names = new Set();
  for (const field of fields) {
    if (field.isConstant === true) continue;
    names.add(field.name);
    const at = join(where, field.name);
    if (!(field.name in expected)) throw new Mismatch(at, "not in the .json");
    if (!(field.name in actual)) throw new Mismatch(at, "not in foxglove's message");
    const e = expected[field.name];
    const a = actual[field.name];
    if (field.isArray !== true) {
      compareScalar(types, field.type, e, a, at);
      continue;
    }
    const elements = ArrayBuffer.isView(a) ? Array.from(a) : a;
    if (!Array.isArray(e)) throw new Mismatch(at, `the .json has ${show(e)}, not an array`);
    if (!Array.isArray(elements)) throw new Mismatch(at, `expected an array, got ${show(a)}`);
    if (field.arrayLength !== undefined && e.length !== field.arrayLength) {
      throw new Mismatch(at,
                         `the .json has ${e.length} elements, the definition ${field.arrayLength}`);
    }
    if (elements.length !== e.length) {
      throw new Mismatch(at, `${elements.length} elements, expected ${e.length}`);
    }
    for (let i = 0; i < e.length; ++i) {
      compareScalar(types, field.type, e[i], elements[i], `${at}[${i}]`);
    }
  }
  for (const key of Object.keys(expected)) {
    if (!names.has(key)) {
      throw new Mismatch(join(where, key), "in the .json but not in the definition");
    }
  }
  for (const key of Object.keys(actual)) {
    if (!names.has(key)) {
      throw new Mismatch(join(where, key), "in foxglove's message but not in the definition");
    }
  }
}

// The .json as MessageWriter takes it: int64/uint64 fields as BigInt (arrays of them as
// BigInt64Array/BigUint64Array); everything else as it is.
function writable(types, fields, json) {
  const out = {};
  for (const field of fields) {
    if (field.isConstant === true) continue;
    const v = json[field.name];
    const one = (x) => (types.has(field.type) ? writable(types, types.get(field.type), x)
                        : kBigIntTypes.has(field.type) ? BigInt(x) : x);
    if (field.isArray !== true) {
      out[field.name] = one(v);
    } else if (kBigIntTypes.has(field.type)) {
      const Typed = field.type === "int64" ? BigInt64Array : BigUint64Array;
      out[field.name] = Typed.from(v, (x) => BigInt(x));
    } else {
      out[field.name] = v.map(one);
    }
  }
  return out;
}

function checkType(dir, stem) {
  const definitions = parse(fs.readFileSync(path.join(dir, `${stem}.msg`), "utf8"), { ros2: true });
  const types = definitionsByName(definitions);
  const root = types.get("");
  const bytes = fs.readFileSync(path.join(dir, `${stem}.cdr`));
  const expected = JSON.parse(fs.readFileSync(path.join(dir, `${stem}.json`), "utf8"));

  // Foxglove's encoding is written whatever the decoding finds, so that tessera's half of the
  // check runs on every type; the first problem is reported.
  let problem;
  try {
    compareDecoded(definitions, types, bytes, expected);
  } catch (e) {
    problem = e;
  }
  try {
    const encoded = new MessageWriter(definitions).writeMessage(writable(types, root, expected));
    fs.writeFileSync(path.join(dir, `${stem}.foxglove.cdr`), encoded);
  } catch (e) {
    problem ??= new Mismatch("", `foxglove cannot encode the .json: ${e.message}`);
  }
  if (problem) throw problem;
}

// Decodes tessera's wire bytes with foxglove's reader and compares them with the .json.
function compareDecoded(definitions, types, bytes, expected) {
  const reader = new MessageReader(definitions);
  let decoded;
  try {
    decoded = reader.readMessage(bytes);
  } catch (e) {
    throw new Mismatch("", `foxglove cannot decode tessera's ${bytes.length} bytes: ${e.message}`);
  }
  const padding = bytes.length >= 4 ? bytes[3] & 3 : 0;
  if (reader.lastReadByteLength() !== bytes.length - padding) {
    throw new Mismatch("", `foxglove read ${reader.lastReadByteLength()} of ${bytes.length} ` +
                           `bytes (${padding} of them Cyclone's padding)`);
  }
  compareMessage(types, types.get(""), expected, decoded, "");
}

function main() {
  const dir = process.argv[2];
  if (!dir) {
    console.error("usage: node wire_check.cjs DIR");
    process.exit(2);
  }
  const stems = fs.readdirSync(dir)
                    .filter((f) => f.endsWith(".cdr") && !f.endsWith(".foxglove.cdr"))
                    .map((f) => f.slice(0, -".cdr".length))
                    .sort();
  if (stems.length === 0) {
    console.error(`FAIL: no .cdr file in ${dir}`);
    process.exit(1);
  }
  let failures = 0;
  for (const stem of stems) {
    const type = stem.replace("__", "/msg/");
    try {
      checkType(dir, stem);
      console.log(`ok ${type}`);
    } catch (e) {
      console.log(`FAIL ${type}: ${e instanceof Mismatch ? e.message : e.stack}`);
      ++failures;
    }
  }
  process.exit(failures === 0 ? 0 : 1);
}

main();
