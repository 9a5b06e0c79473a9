// What the operator page's browser scripts share: Debian's chromium started headless by
// puppeteer-core (from tests/node, never a downloaded browser) with the flags this closed network
// needs, and one checked step per printed line.
'use strict';
const path = require('path');

// `modulesDir`: tests/node/node_modules.
function launchChromium(modulesDir, extraArgs = []) {
  const puppeteer = require(path.join(modulesDir, 'puppeteer-core'));
  return puppeteer.launch({
    executablePath: '/usr/bin/chromium', headless: true,
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

// Runs `main` and exits 1 with the error when it fails.
function run(main) {
  main().catch((error) => { console.error(error.stack || String(error)); process.exit(1); });
}

module.exports = { launchChromium, check, clickLive, run };
