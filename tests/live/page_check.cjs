// Opens tessera's live page in headless Chromium (npm's puppeteer-core driving Debian's
// chromium), waits until the run finished, then checks from the DOM that a map and the robots
// (or, for fusion, the hex cells and image nodes) were drawn, and from a screenshot of the page that the map's and the robots' colours are on
// it. Writes the screenshot to SCREENSHOT.
// Usage: node page_check.cjs CHROMIUM PORT VIEW SCREENSHOT TIMEOUT_S
'use strict';
const puppeteer = require('puppeteer-core');

const [chromium, port, view, screenshot] = process.argv.slice(2, 6);
const timeoutMs = 1000 * Number(process.argv[6] || 120);
const fail = (why) => { console.error(`page_check (${view}): FAIL: ${why}`); process.exit(1); };

(async () => {
  const browser = await puppeteer.launch({
    executablePath: chromium, headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--window-size=1100,750'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1100, height: 750 });
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`http://127.0.0.1:${port}/`, { waitUntil: 'load', timeout: 20000 });
    await page.waitForFunction(() => document.body.dataset.state === 'finished', { timeout: timeoutMs })
      .catch(() => fail('the page never heard that the run finished'));
    // Let the last frame draw.
    await page.waitForFunction(() => Number(document.getElementById('view').dataset.mapCells) > 0,
                               { timeout: 10000 }).catch(() => {});
    const dom = await page.evaluate(() => {
      const c = document.getElementById('view');
      return { view: document.body.dataset.view, messages: Number(document.body.dataset.messages),
               mapCells: Number(c.dataset.mapCells), robots: Number(c.dataset.robots),
               paths: Number(c.dataset.paths), markers: Number(c.dataset.markers),
               summary: document.getElementById('summary').textContent,
               goals: document.getElementById('goals').textContent };
    });
    if (errors.length) fail(`script errors on the page: ${errors.join('; ')}`);
    if (dom.view !== view) fail(`the server says the view is "${dom.view}", expected "${view}"`);
    // A fusion run has no occupancy grid: its map is the hex cells and image nodes (markers).
    if (view === 'fusion' ? !(dom.markers >= 2 && dom.paths >= 2) : !(dom.mapCells > 0)) {
      fail(`no map drawn (${JSON.stringify(dom)})`);
    }
    if (!(dom.robots >= 1)) fail(`no robot drawn (${JSON.stringify(dom)})`);
    const png = await page.screenshot({ path: screenshot, type: 'png' });
    // Read the screenshot's pixels back through an image in the page (no PNG decoder needed).
    const colours = await page.evaluate(async (dataUrl) => {
      const img = new Image();
      img.src = dataUrl;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      const count = { robot: 0, occupied: 0, bobEmpty: 0, bobOccupied: 0, bobUnsensed: 0, imageNodes: 0 };
      const near = (i, r, gg, b) => Math.abs(d[i] - r) < 12 && Math.abs(d[i + 1] - gg) < 12 && Math.abs(d[i + 2] - b) < 12;
      for (let i = 0; i < d.length; i += 4) {
        if (near(i, 0x1f, 0x77, 0xb4)) ++count.robot;         // robot 0's colour (and its path)
        if (near(i, 0, 0, 0)) ++count.occupied;
        if (near(i, 90, 180, 80)) ++count.bobEmpty;            // Figure 5a: green empty
        if (near(i, 205, 45, 40)) ++count.bobOccupied;         // red occupied
        if (near(i, 240, 215, 60)) ++count.bobUnsensed;        // yellow not sensed
        if (near(i, 230, 77, 26)) ++count.imageNodes;           // fusion's image nodes
      }
      return count;
    }, `data:image/png;base64,${Buffer.from(png).toString('base64')}`);
    if (colours.robot < 20) fail(`robot 0's colour is on ${colours.robot} pixels of the screenshot`);
    if (view === 'bob') {
      if (colours.bobEmpty < 200 || colours.bobOccupied < 50) fail(`Figure 5a's colours missing: ${JSON.stringify(colours)}`);
    } else if (view === 'fusion') {
      if (colours.imageNodes < 20) fail(`image nodes on ${colours.imageNodes} pixels of the screenshot`);
    } else if (colours.occupied < 200) {
      fail(`walls (black) on only ${colours.occupied} pixels of the screenshot`);
    }
    // Play / pause / step: the first step shows less of the map than the end; then a picture of
    // the run 40 % of the way through.
    const replay = await page.evaluate(async () => {
      const frame = () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      // How much of the run is drawn: the known cells, or for a fusion run (no grid) its paths' poses.
      const view = document.getElementById('view');
      const drawn = () => Number(document.body.dataset.view === 'fusion' ? view.dataset.pathPoses : view.dataset.mapCells);
      const end = drawn();
      document.getElementById('first').click(); await frame();
      const first = drawn();
      document.getElementById('step').click(); await frame();
      const seek = document.getElementById('seek');
      seek.value = String(Math.round(0.4 * Number(seek.max)));
      seek.dispatchEvent(new Event('input')); await frame();
      return { first, end, steps: Number(seek.max) + 1, clock: document.getElementById('clock').textContent };
    });
    const what = view === 'fusion' ? 'path poses' : 'known cells';
    if (replay.steps > 2 && !(replay.first < replay.end)) fail(`stepping back to the start shows ${replay.first} ${what}, the end ${replay.end}`);
    await page.screenshot({ path: screenshot.replace(/\.png$/, '-mid.png'), type: 'png' });
    console.log(`page_check (${view}): ${dom.messages} messages, ${dom.mapCells} known cells, ` +
                `${dom.robots} robot(s), ${dom.paths} path(s), ${dom.markers} markers; screenshot ` +
                `${JSON.stringify(colours)}; replay: first step ${replay.first} of ${replay.end} ${what}, ${replay.steps} steps`);
  } finally {
    await browser.close();
  }
})().catch((e) => fail(e.stack || String(e)));
