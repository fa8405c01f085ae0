// Collects the shipped example cases into one file the page can fetch:
// [{"name": "hertz", "text": "<the file, byte for byte>"}, ...]: the 2D cases
// (EXAMPLES_DIR/*.json) sorted by name, then the 3D cases (EXAMPLES_DIR/3d/*.json, when that
// folder exists) sorted by name, each with "dimension": 3, so the 2D list keeps its order and
// the page can group the 3D ones. The text is kept as written so the editor shows the same
// layout as `fosls-contact example`.
//
//   node web/scripts/make_examples.mjs solver/examples web/dist/examples.json
import { readdirSync, readFileSync, writeFileSync, renameSync, existsSync } from 'node:fs';
import { basename, join } from 'node:path';

const [sourceDir, outFile] = process.argv.slice(2);
if (!sourceDir || !outFile) {
  console.error('usage: node make_examples.mjs EXAMPLES_DIR OUT.json');
  process.exit(2);
}

/** The cases of one folder, sorted by name (each checked to be JSON). */
function casesIn(dir, extra) {
  return readdirSync(dir).filter((f) => f.endsWith('.json')).sort().map((file) => {
    const text = readFileSync(join(dir, file), 'utf8');
    try {
      JSON.parse(text);
    } catch (e) {
      console.error(`make_examples: ${join(dir, file)} is not valid JSON: ${e.message}`);
      process.exit(1);
    }
    return { name: basename(file, '.json'), text, ...extra };
  });
}

const solidDir = join(sourceDir, '3d');
const examples = [...casesIn(sourceDir, {}), ...(existsSync(solidDir) ? casesIn(solidDir, { dimension: 3 }) : [])];
if (examples.length === 0) {
  console.error(`make_examples: no *.json cases in ${sourceDir}`);
  process.exit(1);
}
const names = examples.map((e) => e.name);
const twice = names.find((n, i) => names.indexOf(n) !== i);
if (twice) {
  console.error(`make_examples: two examples are called ${twice} (a 2D and a 3D one?): the page tells examples apart by name`);
  process.exit(1);
}

const body = JSON.stringify(examples, null, 1) + '\n';
// Rewrite only on change, and atomically, so a running server never serves half a file.
if (!existsSync(outFile) || readFileSync(outFile, 'utf8') !== body) {
  writeFileSync(`${outFile}.tmp`, body);
  renameSync(`${outFile}.tmp`, outFile);
}
