#!/usr/bin/env node
// Drives a viewer.html in headless Chromium through a list of steps and writes
// what the page reported after each as JSON: the browser tests' tool
// (tests/viewer, doc/viewer.md). Same browser and flags as screenshot.js.
//
//   node tools/viewer/probe.js VIEWER.html REPORT.json STEP...
//     state              window.pmapViewer
//     surfaces           each surface's info (id, kind, size, normal, support ...)
//     pixels             each surface's pixels in the current view (and the path's)
//     pixels-alone       the same, each surface drawn alone (nothing in front of it)
//     click-surface:ID   click where surface ID shows (from "pixels"); the selection
//     click-again        click the previous click's point again
//     pick-surface:ID    click where surface ID is (drawn alone) until it is
//                        selected, at most 8 times ("clicks": how many, 0: never)
//     click:X,Y          click the canvas at X,Y (CSS pixels)
//     toggle:ID          click the HUD checkbox #ID
//     zoom-in:N          N wheel steps towards the centre of the canvas
//     frame-all          click the "frame all" button
//     screenshot:FILE    save a PNG of the page
// Every step's entry holds "state" (window.pmapViewer after it) and the
// inspector panel's text ("panel", "" when hidden).
// Exit status: 0 done, 1 the page or a step failed, 2 bad usage or missing
// chromium / playwright-core.
'use strict';
const fs = require('fs');
const path = require('path');
const {die: dieAs, openViewer, withViewerPage, failureMessage} = require('./browser.js');

const die = (status, message) => dieAs('probe.js', status, message);
const TIMEOUT_MS = 20000;

async function panelText(page) {
  return page.$eval('#pmap-inspect', (e) => (e.hidden ? '' : e.innerText));
}

async function settle(page) {  // two animation frames: the page has re-rendered
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function clickAt(page, context, x, y) {
  await page.mouse.click(x, y);
  context.lastClick = [x, y];
  return {at: [x, y]};
}

const STEPS = {
  state: async () => ({}),
  surfaces: async (page) => ({surfaces: await page.evaluate(() => window.pmapViewerTest.surfaces())}),
  pixels: async (page) => ({pixels: await page.evaluate(() => window.pmapViewerTest.surfacePixels())}),
  'pixels-alone': async (page) => ({
    pixels: await page.evaluate(() => window.pmapViewerTest.surfacePixels({alone: true})),
  }),
  'pick-surface': async (page, argument, context) => {
    const id = Number(argument);
    const pixels = await page.evaluate(() => window.pmapViewerTest.surfacePixels({alone: true}));
    const surface = pixels.surfaces.find((s) => s.id === id);
    if (!surface || !surface.at) throw new Error(`surface ${argument} is not in view: cannot pick it`);
    for (let clicks = 1; clicks <= 8; ++clicks) {
      await clickAt(page, context, ...surface.at);
      await settle(page);
      if (await page.evaluate((i) => window.pmapViewer.selected?.id === i, id)) {
        return {at: surface.at, clicks};
      }
    }
    return {at: surface.at, clicks: 0};
  },
  'click-surface': async (page, argument, context) => {
    const id = Number(argument);
    const pixels = await page.evaluate(() => window.pmapViewerTest.surfacePixels());
    const surface = pixels.surfaces.find((s) => s.id === id);
    if (!surface || !surface.at) throw new Error(`surface ${argument} does not show: cannot click it`);
    return clickAt(page, context, ...surface.at);
  },
  'click-again': async (page, argument, context) => {
    if (!context.lastClick) throw new Error('click-again: no click before');
    return clickAt(page, context, ...context.lastClick);
  },
  click: async (page, argument, context) => clickAt(page, context, ...argument.split(',').map(Number)),
  toggle: async (page, argument) => {
    await page.click(`#${argument}`);
    return {checked: await page.isChecked(`#${argument}`)};
  },
  'zoom-in': async (page, argument) => {
    const size = page.viewportSize();
    await page.mouse.move(size.width / 2, size.height / 2);
    for (let i = 0; i < Number(argument || 1); ++i) {
      await page.mouse.wheel(0, -200);
      await settle(page);
    }
    return {};
  },
  'frame-all': async (page) => {
    await page.click('#pmap-frame-all');
    return {};
  },
  screenshot: async (page, argument) => {
    await page.screenshot({path: path.resolve(argument)});
    return {file: path.resolve(argument)};
  },
};

function parseArgs(argv) {
  if (argv.length < 3) die(2, 'usage: node tools/viewer/probe.js VIEWER.html REPORT.json STEP...');
  const [html, report, ...steps] = argv;
  for (const step of steps) {
    if (!STEPS[step.split(':')[0]]) die(2, `unknown step ${step}`);
  }
  if (!fs.existsSync(html)) die(2, `${path.resolve(html)}: no such file`);
  return {html: path.resolve(html), report: path.resolve(report), steps};
}

async function drive(page, options, log) {
  log.initial = await openViewer(page, options.html, TIMEOUT_MS);
  log.steps = [];
  const context = {};
  for (const step of options.steps) {
    const colon = step.indexOf(':');
    const [name, argument] = colon < 0 ? [step, ''] : [step.slice(0, colon), step.slice(colon + 1)];
    const entry = {step, ...(await STEPS[name](page, argument, context))};
    await settle(page);
    entry.state = await page.evaluate(() => ({...window.pmapViewer}));
    entry.panel = await panelText(page);
    log.steps.push(entry);
  }
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const {log, failure} = await withViewerPage('probe.js', {width: 1280, height: 800},
                                              (page, log) => drive(page, options, log));
  fs.writeFileSync(options.report, JSON.stringify({html: options.html, ...log}, null, 2) + '\n');
  if (failure) die(1, failureMessage(options.html, failure, log));
  console.log(`${path.basename(options.html)}: ${options.steps.length} steps (${log.browser}) -> ` +
              options.report);
}

main().catch((error) => die(1, error.message));
