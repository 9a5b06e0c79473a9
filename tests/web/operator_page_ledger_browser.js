// The operator page of a ledger shop in a real browser (Debian's chromium, puppeteer-core): the
// page of one node (PAGE_URL) shows the whole shop. Run by web_ledger_browser_test.cpp with two
// nodes, a job held on the other node's cutter, and a scan that test drops on the other node.
// Checks, without a reload: the page says it reads the ledger and lists both nodes and both
// cutters; the held job of the other node shows its reason and is requeued from this page with
// the token (refused without it); the scan dropped on the other node reaches Done.
// Usage: node operator_page_ledger_browser.js PAGE_URL TOKEN SCAN_NAME NODE_A NODE_B SHOT NODE_MODULES
'use strict';

const [url, token, scanName, nodeA, nodeB, shot, modulesDir] = process.argv.slice(2);
if (!modulesDir) {
  console.error('usage: node operator_page_ledger_browser.js PAGE_URL TOKEN SCAN_NAME NODE_A NODE_B SHOT NODE_MODULES');
  process.exit(2);
}
const { launchChromium, check, clickLive, openDoneJobPage, run } = require('./browser_kit');

async function main() {
  const browser = await launchChromium(modulesDir);
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1400, height: 1000 });
    const errors = [];
    page.on('pageerror', (error) => errors.push(String(error)));
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForFunction(() => document.getElementById('live').textContent === 'live', { timeout: 10000 });
    await page.evaluate(() => { window.__noReload = 'first page'; });
    // The live badge comes with the stream; the headline with the overview, read at the same time:
    // reading it at once raced with that read ("reading the store...", one failure in a few runs).
    await page.waitForFunction(() => document.getElementById('headline').textContent !== 'reading the store...',
                               { timeout: 10000 });
    const headline = await page.$eval('#headline', (node) => node.textContent);
    check(headline.startsWith('ledger '), `the page reads the shop's ledger: ${headline}`);
    await page.waitForFunction((a, b) => {
      const text = document.getElementById('stations').textContent;
      return text.includes(a) && text.includes(b);
    }, { timeout: 15000 }, nodeA, nodeB);
    check(true, `both nodes are listed: ${nodeA}, ${nodeB}`);

    await page.waitForSelector('#column-held li[data-job]', { timeout: 30000 });
    const heldId = await page.$eval('#column-held li[data-job]', (item) => item.dataset.job);
    const reason = await page.$eval('#column-held li[data-job] .reason', (item) => item.textContent);
    check(reason.length > 0, `the other node's held job ${heldId} shows its reason: ${reason}`);
    await clickLive(page, `#column-held li[data-job="${heldId}"] button.requeue`);
    await page.waitForFunction(() => document.getElementById('message').textContent.includes('token'), { timeout: 10000 });
    check(true, 'requeue without a token refused: ' + await page.$eval('#message', (node) => node.textContent));
    await page.type('#token', token);
    await clickLive(page, `#column-held li[data-job="${heldId}"] button.requeue`);
    await page.waitForFunction(() => document.getElementById('message').className === 'ok', { timeout: 10000 });
    check(true, 'requeued from this page: ' + await page.$eval('#message', (node) => node.textContent));

    await page.waitForFunction((name) => {
      const done = document.querySelector('#column-done');
      return done && done.textContent.includes(name);
    }, { timeout: 120000 }, scanName);
    check(true, `the scan dropped on ${nodeA} reached Done on ${nodeB}'s page`);
    await page.waitForFunction((id) => document.querySelector(`#column-done li[data-job="${id}"]`), { timeout: 120000 }, heldId);
    check(true, `the requeued job ${heldId} was cut`);
    await page.screenshot({ path: shot, fullPage: true });
    // Its page, from the shop's shared folder: the molds' stretch maps and the ledger's history.
    await openDoneJobPage(page, heldId);
    const history = await page.$$eval('#job-history li', (items) => items.map((item) => item.textContent));
    check(history.some((line) => line.includes('requeued')) && history.some((line) => line.includes('held')),
          `the job's page shows its pictures and its history from the ledger (${history.length} events)`);
    check(await page.evaluate(() => window.__noReload) === 'first page', 'the page was never reloaded');
    check(errors.length === 0, 'no script error on the page ' + errors.join('; '));
  } finally {
    await browser.close();
  }
}

run(main);
