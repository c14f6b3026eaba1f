// Connects npm's @foxglove/ws-protocol client (on npm's `ws`) to a running `tessera ... --serve`,
// subscribes to /map and decodes the maps it receives with @foxglove/rosmsg2-serialization
// against the schema the server advertised. Passes when at least one map decodes (width x height
// cells, every value -1 or 0..100) before the server says the run finished.
// Usage: node ws_client_check.cjs PORT TIMEOUT_S
'use strict';
const { FoxgloveClient } = require('@foxglove/ws-protocol');
const WebSocket = require('ws');
const { parse } = require('@foxglove/rosmsg');
const { MessageReader } = require('@foxglove/rosmsg2-serialization');

const [port, timeoutS] = [process.argv[2], Number(process.argv[3] || 60)];
const fail = (why) => { console.error(`ws_client_check: FAIL: ${why}`); process.exit(1); };
setTimeout(() => fail(`no decoded map within ${timeoutS} s`), timeoutS * 1000);

const client = new FoxgloveClient({
  ws: new WebSocket(`ws://127.0.0.1:${port}`, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]),
});
let reader = null, mapSubscription = null, finished = false, decoded = 0, serverName = '';
client.on('error', (e) => fail(`client error: ${e && e.message}`));
client.on('serverInfo', (info) => { serverName = info.name; });
client.on('advertise', (channels) => {
  for (const c of channels) {
    if (c.topic !== '/map') continue;
    if (c.encoding !== 'cdr' || c.schemaEncoding !== 'ros2msg') fail(`/map is ${c.encoding}/${c.schemaEncoding}`);
    reader = new MessageReader(parse(c.schema, { ros2: true }));
    mapSubscription = client.subscribe(c.id);
  }
});
client.on('status', (s) => { if (s.id === 'tessera.finished') finished = true; });
client.on('message', ({ subscriptionId, data }) => {
  if (subscriptionId !== mapSubscription) return;
  const map = reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  const { width, height, resolution } = map.info;
  if (map.data.length !== width * height) fail(`map data ${map.data.length} != ${width} x ${height}`);
  for (const v of map.data) if (v !== -1 && (v < 0 || v > 100)) fail(`map value ${v}`);
  if (!(resolution > 0)) fail(`resolution ${resolution}`);
  if (finished) fail('the first map arrived only after the run finished (not live)');
  ++decoded;
  const known = map.data.filter((v) => v >= 0).length;
  console.log(`ws_client_check: ${serverName}: map ${width} x ${height} at ${resolution.toFixed(3)} m, ` +
              `${known} known cells, decoded while the run was in progress`);
  client.close();
  process.exit(0);
});
