// What the operator page's browser scripts share: Debian's chromium started headless by
// puppeteer-core (from tests/node, never a downloaded browser) with the flags this closed network
// needs, and one checked step per printed line.
'use strict';
const path = require('path');

// `modulesDir`: tests/node/node_modules; `options`: more of puppeteer's launch options.
function launchChromium(modulesDir, extraArgs = [], options = {}) {
  const puppeteer = require(path.join(modulesDir, 'puppeteer-core'));
  return puppeteer.launch({
    ...options, executablePath: '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', ...extraArgs],
  });
}

function check(condition, what) {
  if (!condition) throw new Error('FAILED: ' + what);
  console.log('ok: ' + what);
}

// Clicks `selector`; the page redraws its lists on every live event, so an element found may be
// replaced before the click lands: then it is found again (up to 20 times).
async function clickLive(page, selector) {
  for (let attempt = 0; ; ++attempt) {
    try {
      await page.click(selector);
      return;
    } catch (error) {
      if (attempt >= 20 || !/detached|not clickable|No node found/.test(String(error))) throw error;
      await new Promise((resolve) => setTimeout(resolve, 50));
    }
  }
}

// Opens job `jobId`'s page by its link in the Done column and waits until its pictures have loaded.
// (A click that lands while the queue is being redrawn is lost, as a person's would be: again.)
async function openDoneJobPage(page, jobId) {
  for (let attempt = 0; attempt < 5; ++attempt) {
    await clickLive(page, `#column-done li[data-job="${jobId}"] a`);
    const opened = await page.waitForFunction(() => !document.getElementById('job-view').hidden, { timeout: 3000 })
      .then(() => true, () => false);
    if (opened) break;
  }
  await page.waitForFunction(() => document.querySelectorAll('#job-pictures img').length > 0 &&
                                 [...document.querySelectorAll('#job-pictures img')].every((img) => img.complete && img.naturalWidth > 0),
                             { timeout: 30000 });
}

// Runs `main` and exits 1 with the error when it fails.
function run(main) {
  main().catch((error) => { console.error(error.stack || String(error)); process.exit(1); });
}

module.exports = { launchChromium, check, clickLive, openDoneJobPage, run };
