#!/usr/bin/env node
// Validates a glTF 2.0 file (.glb or .gltf) with the Khronos glTF validator.
// Prints {"file", "numErrors", "numWarnings", "numInfos", "numHints",
// "messages": [...]} as JSON; exit 0 when there is no error, 1 on validation
// errors, 2 when the file cannot be read or validated at all.
// Usage: node tools/web/validate-gltf.js map.glb   (after `npm ci --prefix tools/web`)
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function main() {
  const file = process.argv[2];
  if (!file) {
    console.error('usage: node validate-gltf.js FILE.glb');
    return 2;
  }
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))),
  });
  const issues = report.issues;
  console.log(JSON.stringify({
    file,
    numErrors: issues.numErrors,
    numWarnings: issues.numWarnings,
    numInfos: issues.numInfos,
    numHints: issues.numHints,
    messages: issues.messages.map((m) => ({
      code: m.code, severity: m.severity, message: m.message, pointer: m.pointer,
    })),
  }, null, 1));
  return issues.numErrors > 0 ? 1 : 0;
}

main().then((code) => process.exit(code), (err) => {
  console.error(`validate-gltf: ${err && err.message ? err.message : err}`);
  process.exit(2);
});
