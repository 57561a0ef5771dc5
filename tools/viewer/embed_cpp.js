// Build step of libs/viewer: turns text files (the esbuild bundle, the page
// template) into a C++ source that defines
//   std::string_view pmap::viewer::assets::NAME()
// for each NAME=FILE argument. The bytes go into unsigned char arrays, not
// string literals, so no compiler limit on literal length applies.
//
//   node embed_cpp.js OUT.cpp NAME=FILE [NAME=FILE ...]
//
// Fails if a script asset could close or confuse its <script> element
// ("</script" or "<!--").
'use strict';
const fs = require('fs');
const path = require('path');

const BYTES_PER_LINE = 24;

function fail(message) {
  console.error(`embed_cpp.js: ${message}`);
  process.exit(1);
}

function checkScriptSafe(name, file, text) {
  if (!file.endsWith('.js')) return;
  for (const bad of ['</script', '<!--']) {
    if (text.toLowerCase().includes(bad)) {
      fail(`${file} contains "${bad}": it cannot be inlined in a <script> element (${name})`);
    }
  }
}

function byteArray(bytes) {
  const lines = [];
  for (let i = 0; i < bytes.length; i += BYTES_PER_LINE) {
    lines.push('    ' + Array.from(bytes.subarray(i, i + BYTES_PER_LINE)).join(',') + ',');
  }
  return lines.join('\n');
}

function assetSource(name, file) {
  if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(name)) fail(`bad asset name '${name}'`);
  const bytes = fs.readFileSync(file);
  checkScriptSafe(name, file, bytes.toString('latin1'));
  const array = `k_${name}`;
  return [
    `// ${path.basename(file)}: ${bytes.length} bytes`,
    `const unsigned char ${array}[] = {`,
    byteArray(bytes),
    '    0};',
    `}  // namespace`,
    `std::string_view ${name}() {`,
    `  return {reinterpret_cast<const char*>(${array}), sizeof(${array}) - 1};`,
    `}`,
    `namespace {`,
  ].join('\n');
}

function main(args) {
  if (args.length < 2) fail('usage: node embed_cpp.js OUT.cpp NAME=FILE [NAME=FILE ...]');
  const [out, ...assets] = args;
  const parts = assets.map((arg) => {
    const eq = arg.indexOf('=');
    if (eq <= 0) fail(`expected NAME=FILE, got '${arg}'`);
    return assetSource(arg.slice(0, eq), arg.slice(eq + 1));
  });
  const text = [
    '// Generated at build time by tools/viewer/embed_cpp.js: do not edit.',
    '#include <string_view>',
    '',
    'namespace pmap::viewer::assets {',
    'namespace {',
    ...parts,
    '}  // namespace',
    '}  // namespace pmap::viewer::assets',
    '',
  ].join('\n');
  fs.mkdirSync(path.dirname(out), {recursive: true});
  fs.writeFileSync(`${out}.tmp`, text);
  fs.renameSync(`${out}.tmp`, out);
}

main(process.argv.slice(2));
