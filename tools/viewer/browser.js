// Headless Chromium for viewer.html, shared by screenshot.js and probe.js
// (doc/viewer.md): Debian's chromium driven by playwright-core, WebGL through
// SwiftShader (ANGLE's; --use-gl=swiftshader no longer gives WebGL), the page
// opened from file:// with the network off.
'use strict';
const fs = require('fs');
const path = require('path');
const {execFileSync} = require('child_process');

const CHROMIUM_ARGS = [
  '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--no-first-run',
];

function die(tool, status, message) {
  console.error(`${tool}: ${message}`);
  process.exit(status);
}

/** $PMAP_CHROMIUM, else /usr/bin/chromium, else chromium on PATH; exits 2 if none. */
function findChromium(tool) {
  const candidates = [process.env.PMAP_CHROMIUM, '/usr/bin/chromium'].filter(Boolean);
  for (const candidate of candidates) {
    if (fs.existsSync(candidate)) return candidate;
  }
  try {
    return execFileSync('sh', ['-c', 'command -v chromium'], {encoding: 'utf8'}).trim();
  } catch {
    return die(tool, 2, 'chromium not found (install Debian\'s chromium: apt-get install ' +
                        'chromium, or set PMAP_CHROMIUM)');
  }
}

function loadPlaywright(tool) {
  try {
    return require('playwright-core');
  } catch {
    return die(tool, 2, `playwright-core not found in ${path.join(__dirname, 'node_modules')}: ` +
                        'run npm ci --prefix tools/viewer');
  }
}

/** Records requests that are not to the page itself (file:, data:, blob:) and errors. */
function watchPage(page, log) {
  page.on('request', (request) => {
    if (!/^(file|data|blob):/.test(request.url())) log.externalRequests.push(request.url());
  });
  page.on('console', (message) => {
    if (message.type() === 'error') log.consoleErrors.push(message.text());
  });
  page.on('pageerror', (error) => log.pageErrors.push(error.message));
}

/** window.pmapViewer once `condition` holds in the page. */
async function viewerState(page, timeoutMs, condition) {
  await page.waitForFunction(condition, null, {timeout: timeoutMs});
  return page.evaluate(() => ({...window.pmapViewer}));
}

/**
 * Opens `html` and waits for the first frame; throws if the viewer failed.
 * The state has `drawnAtLoad`: whether the first frame was drawn when the
 * page's load event fired (what a plain `chromium --screenshot` relies on).
 */
async function openViewer(page, html, timeoutMs) {
  await page.addInitScript(() => window.addEventListener('load', () => {
    window.pmapDrawnAtLoad = Boolean(window.pmapViewer && window.pmapViewer.ready);
  }));
  await page.goto(`file://${html}`);
  await viewerState(page, timeoutMs, () => window.pmapViewer &&
                    (window.pmapViewer.ready || window.pmapViewer.error));
  await page.waitForFunction(() => document.readyState === 'complete', null, {timeout: timeoutMs});
  const state = await page.evaluate(() => ({...window.pmapViewer,
                                            drawnAtLoad: window.pmapDrawnAtLoad === true}));
  if (!state.ready) throw new Error(`the viewer failed: ${state.error}`);
  return state;
}

/**
 * Starts Chromium, opens a page of `width` x `height` CSS pixels, runs
 * `drive(page, log)`, closes the browser. Returns {log, failure}; exits 2 if
 * the browser cannot start.
 */
async function withViewerPage(tool, {width, height}, drive) {
  const executablePath = findChromium(tool);
  const {chromium} = loadPlaywright(tool);
  const log = {externalRequests: [], consoleErrors: [], pageErrors: []};
  const browser = await chromium
      .launch({executablePath, headless: true, args: CHROMIUM_ARGS, timeout: 30000})
      .catch((error) => die(tool, 2, `cannot start ${executablePath}: ${error.message.split('\n')[0]}`));
  let failure = null;
  try {
    log.browser = browser.version();
    const context = await browser.newContext({viewport: {width, height}, deviceScaleFactor: 1,
                                              offline: true});
    const page = await context.newPage();
    watchPage(page, log);
    await drive(page, log);
  } catch (error) {
    failure = error;
  } finally {
    await browser.close();
  }
  return {log, failure};
}

/** One line naming the failure and the page's errors. */
function failureMessage(html, failure, log) {
  const errors = [...log.pageErrors, ...log.consoleErrors].map((e) => e.split('\n')[0]).join(' | ');
  return `${html}: ${failure.message.split('\n')[0]}${errors ? ` (page: ${errors})` : ''}`;
}

module.exports = {CHROMIUM_ARGS, die, viewerState, openViewer, withViewerPage, failureMessage};
