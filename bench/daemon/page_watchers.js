// N operator pages watching lastcutd at once: one headless chromium (Debian's), the real page in
// N browser contexts (as N browsers), each recording how late every live event arrived (the browser's clock at arrival
// minus the event's published_ms, one machine so one clock). On SIGTERM (or after LIMIT_S) prints
// one JSON line: pages, events seen, the latency's median, p99 and max in ms, and the events later
// than 1 s. Used by load_bench.sh WATCHERS.
// Usage: node page_watchers.js URL PAGES NODE_MODULES [LIMIT_S]
'use strict';

const [url, pagesArgument, modulesDir, limitArgument] = process.argv.slice(2);
const { launchChromium } = require('../../tests/web/browser_kit');
const pageCount = Number(pagesArgument);

async function main() {
  const browser = await launchChromium(modulesDir, ['--disable-background-timer-throttling', '--disable-renderer-backgrounding',
                                                    '--disable-backgrounding-occluded-windows'],
                                       // The summary is made on SIGTERM: puppeteer must not close the browser first.
                                       { handleSIGTERM: false, handleSIGINT: false });
  const pages = [];
  for (let i = 0; i < pageCount; ++i) {
    // Each page in a browser context of its own, as N browsers: a context has its own connections
    // (one profile allows 6 per host, which 6 pages' live streams would fill).
    const context = await browser.createBrowserContext();
    const page = await context.newPage();
    // The page's own live stream measures: every EventSource it opens notes each event's delay.
    await page.evaluateOnNewDocument(() => {
      window.__late = [];
      const Original = window.EventSource;
      window.EventSource = function measured(url, options) {
        const source = new Original(url, options);
        for (const kind of ['job', 'cutter']) {
          source.addEventListener(kind, (message) => {
            const data = JSON.parse(message.data);
            if (data.published_ms) window.__late.push(Date.now() - data.published_ms);
          });
        }
        return source;
      };
    });
    await page.goto(url, { waitUntil: 'load' });
    pages.push(page);
  }
  await Promise.all(pages.map((page) => page.waitForFunction(
    () => document.getElementById('live').textContent === 'live', { timeout: 30000 })));
  console.error(`page_watchers: ${pageCount} pages live`);
  const finish = async () => {
    const late = [];
    for (const page of pages) late.push(...await page.evaluate(() => window.__late));
    late.sort((a, b) => a - b);
    const at = (q) => (late.length ? late[Math.min(late.length - 1, Math.floor(q * late.length))] : 0);
    console.log(JSON.stringify({ pages: pageCount, events: late.length, median_ms: at(0.5), p99_ms: at(0.99),
                                 max_ms: late.length ? late[late.length - 1] : 0, over_1s: late.filter((ms) => ms > 1000).length }));
    await browser.close();
    process.exit(0);
  };
  process.on('SIGTERM', finish);
  if (limitArgument) setTimeout(finish, Number(limitArgument) * 1000);
}

main().catch((error) => { console.error(error.stack || String(error)); process.exit(1); });
