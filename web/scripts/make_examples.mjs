// Collects the shipped example cases (solver/examples/*.json) into one file the page can
// fetch: [{"name": "hertz", "text": "<the file, byte for byte>"}, ...] sorted by name.
// The text is kept as written so the editor shows the same layout as `fosls-contact example`.
//
//   node web/scripts/make_examples.mjs solver/examples web/dist/examples.json
import { readdirSync, readFileSync, writeFileSync, renameSync, existsSync } from 'node:fs';
import { basename, join } from 'node:path';

const [sourceDir, outFile] = process.argv.slice(2);
if (!sourceDir || !outFile) {
  console.error('usage: node make_examples.mjs EXAMPLES_DIR OUT.json');
  process.exit(2);
}

const files = readdirSync(sourceDir).filter((f) => f.endsWith('.json')).sort();
if (files.length === 0) {
  console.error(`make_examples: no *.json cases in ${sourceDir}`);
  process.exit(1);
}
const examples = files.map((file) => {
  const text = readFileSync(join(sourceDir, file), 'utf8');
  try {
    JSON.parse(text);
  } catch (e) {
    console.error(`make_examples: ${file} is not valid JSON: ${e.message}`);
    process.exit(1);
  }
  return { name: basename(file, '.json'), text };
});

const body = JSON.stringify(examples, null, 1) + '\n';
// Rewrite only on change, and atomically, so a running server never serves half a file.
if (!existsSync(outFile) || readFileSync(outFile, 'utf8') !== body) {
  writeFileSync(`${outFile}.tmp`, body);
  renameSync(`${outFile}.tmp`, outFile);
}
