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
const {die: dieAs, viewerState, openViewer, withViewerPage, failureMessage} = require('./browser.js');

const die = (status, message) => dieAs('screenshot.js', status, message);

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

async function rect(page, selector) {
  return page.$eval(selector, (element) => {
    const r = element.getBoundingClientRect();
    return {x: Math.round(r.x), y: Math.round(r.y), width: Math.round(r.width),
            height: Math.round(r.height)};
  });
}

async function drive(page, options, log) {
  log.initial = await openViewer(page, options.html, options.timeoutMs);
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
  const {log, failure} = await withViewerPage('screenshot.js', options,
                                              (page, log) => drive(page, options, log));
  const report = {html: options.html, screenshot: options.png, ...log};
  if (options.report) fs.writeFileSync(options.report, JSON.stringify(report, null, 2) + '\n');
  if (failure) die(1, failureMessage(options.html, failure, log));
  const state = log.afterToggle ?? log.initial;
  console.log(`${path.basename(options.html)}: ${state.triangles} triangles and ${state.points} ` +
              `points drawn (${log.browser}) -> ${options.png}`);
}

main().catch((error) => die(1, error.message));
