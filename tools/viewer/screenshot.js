#!/usr/bin/env node
// Opens a viewer.html from disk in headless Chromium (Debian's chromium, WebGL
// through SwiftShader, no network), waits until the viewer has drawn its first
// frame and saves a screenshot (doc/viewer.md).
//
//   node tools/viewer/screenshot.js VIEWER.html OUT.png [options]
//     --points          tick the "raw points" toggle (if enabled) before the screenshot
//     --report FILE     write what was drawn (window.pmapViewer, the canvas and
//                       HUD rectangles, requests, console errors) as JSON
//     --width W --height H   viewport in CSS pixels (default 1280 x 800)
//     --timeout-ms MS   how long to wait for the first frame (default 20000)
// The browser is $PMAP_CHROMIUM, else /usr/bin/chromium, else chromium on
// PATH. Needs playwright-core: npm ci --prefix tools/viewer.
// Exit status: 0 drawn, 1 the page failed (error printed), 2 bad usage or
// missing chromium / playwright-core.
'use strict';
const fs = require('fs');
const path = require('path');
const {execFileSync} = require('child_process');

const CHROMIUM_ARGS = [
  '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--no-first-run',
];

function die(status, message) {
  console.error(`screenshot.js: ${message}`);
  process.exit(status);
}

function parseArgs(argv) {
  const options = {points: false, report: null, width: 1280, height: 800, timeoutMs: 20000};
  const positional = [];
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => (i + 1 < argv.length ? argv[++i] : die(2, `${arg} needs a value`));
    if (arg === '--points') options.points = true;
    else if (arg === '--report') options.report = value();
    else if (arg === '--width') options.width = Number(value());
    else if (arg === '--height') options.height = Number(value());
    else if (arg === '--timeout-ms') options.timeoutMs = Number(value());
    else if (arg.startsWith('--')) die(2, `unknown option ${arg}`);
    else positional.push(arg);
  }
  if (positional.length !== 2) {
    die(2, 'usage: node tools/viewer/screenshot.js VIEWER.html OUT.png [--points] [--report FILE]');
  }
  [options.html, options.png] = positional.map((p) => path.resolve(p));
  if (!fs.existsSync(options.html)) die(2, `${options.html}: no such file`);
  return options;
}

function findChromium() {
  const candidates = [process.env.PMAP_CHROMIUM, '/usr/bin/chromium'].filter(Boolean);
  for (const candidate of candidates) {
    if (fs.existsSync(candidate)) return candidate;
  }
  try {
    return execFileSync('sh', ['-c', 'command -v chromium'], {encoding: 'utf8'}).trim();
  } catch {
    return die(2, 'chromium not found (install Debian\'s chromium: apt-get install chromium, ' +
                  'or set PMAP_CHROMIUM)');
  }
}

function loadPlaywright() {
  try {
    return require('playwright-core');
  } catch {
    return die(2, `playwright-core not found in ${path.join(__dirname, 'node_modules')}: ` +
                  'run npm ci --prefix tools/viewer');
  }
}

/** Records every request that is not to the page itself (file:, data:, blob:). */
function watchPage(page, log) {
  page.on('request', (request) => {
    if (!/^(file|data|blob):/.test(request.url())) log.externalRequests.push(request.url());
  });
  page.on('console', (message) => {
    if (message.type() === 'error') log.consoleErrors.push(message.text());
  });
  page.on('pageerror', (error) => log.pageErrors.push(error.message));
}

async function rect(page, selector) {
  return page.$eval(selector, (element) => {
    const r = element.getBoundingClientRect();
    return {x: Math.round(r.x), y: Math.round(r.y), width: Math.round(r.width),
            height: Math.round(r.height)};
  });
}

async function viewerState(page, timeoutMs, condition) {
  await page.waitForFunction(condition, null, {timeout: timeoutMs});
  return page.evaluate(() => ({...window.pmapViewer}));
}

async function drive(page, options, log) {
  await page.goto(`file://${options.html}`);
  log.initial = await viewerState(page, options.timeoutMs,
                                  () => window.pmapViewer && (window.pmapViewer.ready ||
                                                              window.pmapViewer.error));
  if (!log.initial.ready) throw new Error(`the viewer failed: ${log.initial.error}`);
  if (options.points) {
    log.toggleDisabled = await page.isDisabled('#pmap-points-toggle');  // no raw points
    if (!log.toggleDisabled) await page.check('#pmap-points-toggle');
    log.afterToggle = await viewerState(page, options.timeoutMs,
                                        () => window.pmapViewer.pointsVisible === true ||
                                              document.getElementById('pmap-points-toggle').disabled);
  }
  log.canvas = await rect(page, '#pmap-canvas');
  log.hud = await rect(page, '#pmap-hud');
  log.title = await page.title();
  await page.screenshot({path: options.png});
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const executablePath = findChromium();
  const {chromium} = loadPlaywright();
  const log = {html: options.html, screenshot: options.png, externalRequests: [],
               consoleErrors: [], pageErrors: []};
  const browser = await chromium
      .launch({executablePath, headless: true, args: CHROMIUM_ARGS, timeout: 30000})
      .catch((error) => die(2, `cannot start ${executablePath}: ${error.message.split('\n')[0]}`));
  let failure = null;
  try {
    log.browser = browser.version();
    const context = await browser.newContext({
      viewport: {width: options.width, height: options.height}, deviceScaleFactor: 1,
      offline: true});
    const page = await context.newPage();
    watchPage(page, log);
    await drive(page, options, log);
  } catch (error) {
    failure = error;
  } finally {
    await browser.close();
  }
  if (options.report) fs.writeFileSync(options.report, JSON.stringify(log, null, 2) + '\n');
  if (failure) {
    const errors = [...log.pageErrors, ...log.consoleErrors].map((e) => e.split('\n')[0]).join(' | ');
    die(1, `${options.html}: ${failure.message.split('\n')[0]}${errors ? ` (page: ${errors})` : ''}`);
  }
  const state = log.afterToggle ?? log.initial;
  console.log(`${path.basename(options.html)}: ${state.triangles} triangles and ${state.points} ` +
              `points drawn (${log.browser}) -> ${options.png}`);
}

main().catch((error) => die(1, error.message));
