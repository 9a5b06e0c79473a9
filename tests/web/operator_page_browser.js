// The operator page in a real browser: Debian's chromium, driven by puppeteer-core (tests/node).
// Run by web_browser_test.cpp against a running lastcutd whose one job is held (its cutter
// dropped the line); the test drops a second scan, and this script checks, without ever
// reloading the page: the new scan moves through the queue's columns to Done, the held job
// shows its reason and is refused without a token and requeued with it, and a hide file
// uploaded from the page is accepted; while the requeued job is cut, the cutter's card shows the
// layout with the piece being cut highlighted. Screenshots go to SHOTS_DIR.
// Usage: node operator_page_browser.js URL TOKEN WATCH_DIR SCAN_FILE HIDE_FILE SHOTS_DIR NODE_MODULES
'use strict';
const fs = require('fs');
const path = require('path');

const [url, token, watchDir, scanFile, hideFile, shotsDir, modulesDir] = process.argv.slice(2);
if (!modulesDir) {
  console.error('usage: node operator_page_browser.js URL TOKEN WATCH_DIR SCAN_FILE HIDE_FILE SHOTS_DIR NODE_MODULES');
  process.exit(2);
}
const { launchChromium, check, clickLive, openDoneJobPage, run } = require('./browser_kit');

// The queue column a job (by scan name or id) is listed in now, or null.
function columnOf(page, text) {
  return page.evaluate((wanted) => {
    for (const item of document.querySelectorAll('.column li')) {
      if (item.textContent.includes(wanted)) return item.closest('.column').id.replace('column-', '');
    }
    return null;
  }, text);
}

async function main() {
  const browser = await launchChromium(modulesDir);
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1400, height: 1000 });
    const consoleErrors = [];
    page.on('pageerror', (error) => consoleErrors.push(String(error)));
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForFunction(() => document.getElementById('live').textContent === 'live', { timeout: 10000 });
    check(true, 'the page opened and follows the live events');
    await page.evaluate(() => { window.__noReload = 'still the first page'; });

    // The held job, with its reason, in the Held column.
    await page.waitForSelector('#column-held li[data-job]', { timeout: 10000 });
    const heldId = await page.$eval('#column-held li[data-job]', (item) => item.dataset.job);
    const heldReason = await page.$eval('#column-held li[data-job] .reason', (item) => item.textContent);
    check(heldReason.includes('stopped while cutting'), `the held job ${heldId} shows its reason: ${heldReason}`);

    // A scan dropped now goes through the columns without a reload.
    const seen = [];
    const name = path.basename(scanFile);
    const watcher = setInterval(async () => {
      const column = await columnOf(page, name).catch(() => null);
      if (column && seen[seen.length - 1] !== column) seen.push(column);
    }, 50);
    fs.copyFileSync(scanFile, path.join(watchDir, '.' + name + '.part'));
    fs.renameSync(path.join(watchDir, '.' + name + '.part'), path.join(watchDir, name));
    await page.waitForFunction((wanted) => {
      const done = document.querySelector('#column-done');
      return done && done.textContent.includes(wanted);
    }, { timeout: 120000 }, name);
    clearInterval(watcher);
    if (seen[seen.length - 1] !== 'done') seen.push('done');  // the wait above saw it there
    check(seen.length >= 3, `the new scan moved through ${seen.join(' -> ')} without a reload`);
    await page.screenshot({ path: path.join(shotsDir, 'operator-page-overview.png'), fullPage: true });

    // Requeue without the token: refused with one clear line; the job stays held.
    await clickLive(page, `#column-held li[data-job="${heldId}"] button.requeue`);
    await page.waitForFunction(() => document.getElementById('message').textContent.includes('token'), { timeout: 10000 });
    const refusal = await page.$eval('#message', (node) => node.textContent);
    check(refusal.startsWith('this action needs a token'), `requeue without a token refused: ${refusal}`);
    check(await columnOf(page, heldId) === 'held', 'the job is still held');

    // With the token: requeued, then cut.
    await page.type('#token', token);
    await clickLive(page, `#column-held li[data-job="${heldId}"] button.requeue`);
    await page.waitForFunction(() => document.getElementById('message').className === 'ok', { timeout: 10000 });
    check(true, 'requeued with the token: ' + await page.$eval('#message', (node) => node.textContent));
    // While it is cut: the cutter's card draws the layout on the table, the piece being cut highlighted.
    await page.waitForSelector('.card.cutter svg.table .piece.cutting', { timeout: 60000 });
    const cutting = await page.$eval('.card.cutter .pieces-text', (node) => node.textContent);
    check(/cutting \S/.test(cutting), `the cutter's table shows the piece being cut: ${cutting}`);
    await page.screenshot({ path: path.join(shotsDir, 'operator-page-cutter.png') });
    await page.waitForFunction((id) => {
      const done = document.querySelector('#column-done');
      return done && done.querySelector(`li[data-job="${id}"]`);
    }, { timeout: 120000 }, heldId);
    check(true, `the requeued job ${heldId} was cut`);

    // A hide uploaded from the page is placed on the cutter's table.
    const input = await page.$('#hide-file');
    await input.uploadFile(hideFile);
    await page.click('#hide-load');
    await page.waitForFunction(() => document.getElementById('message').textContent.includes('now lies on cutter'),
                               { timeout: 10000 });
    check(true, 'hide upload: ' + await page.$eval('#message', (node) => node.textContent));
    // A leather job waited for a hide: the hide is nested and cut, and its card shows the layout,
    // the share of the hide the pieces use and what is left (the offcut).
    await page.waitForFunction(() => [...document.querySelectorAll('.card.hide')].some((card) =>
      card.querySelector('.state').textContent.startsWith('cut') && card.querySelector('.figures') &&
      card.querySelector('img').complete && card.querySelector('img').naturalWidth > 0), { timeout: 180000 });
    const hideFigures = await page.$eval('.card.hide .figures', (node) => node.textContent);
    check(/^\d+ pieces, \d+ % of its usable area, offcut [\d.]+ of [\d.]+ m\u00b2(, \d+ of \d+ pairs mirrored about the backbone)?$/.test(hideFigures),
          `the hide's card shows its layout and figures: ${hideFigures}`);
    // The last 24 hours: three jobs cut, in the plots per hour and the yield of each material.
    await page.waitForFunction(() => document.getElementById('day-summary').textContent.startsWith('3 job(s)'),
                               { timeout: 30000 });
    const summary = await page.$eval('#day-summary', (node) => node.textContent);
    const bars = await page.$$eval('.plot .bar', (all) => all.filter((bar) => Number(bar.getAttribute('height')) > 0).length);
    check(/yield .*leather \d+ %/.test(summary) && bars >= 3, `the day's plots: ${summary} (${bars} bars drawn)`);
    await page.screenshot({ path: path.join(shotsDir, 'operator-page-hides-and-day.png'), fullPage: true });

    // The job page: its pictures and report, by the link in the queue.
    await openDoneJobPage(page, heldId);
    check(true, 'the job page shows its pictures');
    await page.screenshot({ path: path.join(shotsDir, 'operator-page-job.png'), fullPage: true });

    check(await page.evaluate(() => window.__noReload) === 'still the first page', 'the page was never reloaded');
    check(consoleErrors.length === 0, 'no script error on the page ' + consoleErrors.join('; '));
  } finally {
    await browser.close();
  }
}

run(main);
