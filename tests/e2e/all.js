// Runs every end-to-end test file (`npm test`), each in a `node --test` of its own: two at a time,
// longest first, so that the long files do not end up waiting for each other at the end, then the files
// whose checks time the page's responsiveness one at a time, with nothing beside them. A single file
// spends most of its time waiting for frames and page events (SwiftShader, JupyterLab, the kernel), so
// two share this machine's two cores without slowing each other much. Each file's report is printed
// when it ends, with its wall time; the exit status is non-zero when any file failed.
// `E2E_JOBS=1 npm test` runs them one at a time.

import { spawn } from 'node:child_process';
import { readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

// Longest first (wall times measured one at a time here, in seconds, roughly).
const SHARED = [
  // The notebook's figures start under JupyterLab and a kernel on a busy page: it runs beside lighter
  // files than the soak's twelve figures.
  'notebook.test.js', // 150
  'teaching.test.js', // 50
  'phone.test.js', // 85
  'soak.test.js', // 100
  'page.test.js', // 55
  'element.test.js', // 45
  'table.test.js', // 45
  'course.test.js', // 35
  'semester.test.js', // 30
  'compare.test.js', // 28
  'share.test.js', // 25
  'languages.test.js', // 30
  'record.test.js', // 12
  'package.test.js', // 25
  'editing.test.js', // 24
  'device-loss.test.js', // 17
  'lab.test.js', // 16
  'widget.test.js', // 12
  'book.test.js', // 12
  'assets.test.js', // 10
  'clip.test.js', // 8
  'interpolant.test.js', // 7
  'squares.test.js', // 4
  'plane.test.js', // 15
  'march.test.js', // 40
  'levels.test.js', // 20
  'size.test.js', // 0.1
  'frame-cost.test.js', // 0.3
  'slabs.test.js', // 5
  'hooks.test.js', // 0.2
  'api.test.js', // 0.1
  'read.test.js', // 0.3
  'words.test.js', // 0.5
];
// A click on a figure drawing a heavy frame must be handled within a second, and the page's long tasks
// are counted: these run alone.
const ALONE = ['fallback.test.js', 'lod.test.js', 'thread.test.js'];

const jobs = Number(process.env.E2E_JOBS ?? 2);
if (!Number.isInteger(jobs) || jobs < 1) {
  console.error(`all.js: E2E_JOBS must be a whole number from 1 up, not "${process.env.E2E_JOBS}"`);
  process.exit(1);
}

// A new test file goes in one of the lists, or it would never run.
const unlisted = readdirSync(here).filter((f) => f.endsWith('.test.js') && ![...SHARED, ...ALONE].includes(f));
if (unlisted.length) {
  console.error(`all.js: place ${unlisted.join(', ')} in SHARED or ALONE`);
  process.exit(1);
}

function run(file) {
  const started = Date.now();
  return new Promise((resolve) => {
    const child = spawn(process.execPath, ['--test', file], { cwd: here, stdio: ['ignore', 'pipe', 'pipe'] });
    const output = [];
    child.stdout.on('data', (chunk) => output.push(chunk));
    child.stderr.on('data', (chunk) => output.push(chunk));
    child.on('close', (code, signal) => {
      const seconds = ((Date.now() - started) / 1000).toFixed(1);
      process.stdout.write(`# ${file}\n${Buffer.concat(output).toString()}`);
      process.stdout.write(`# ${file}: ${code === 0 ? 'passed' : `failed (${signal ?? `exit ${code}`})`} in ${seconds} s\n`);
      resolve({ file, ok: code === 0, seconds });
    });
  });
}

async function pool(files, width) {
  const queue = [...files];
  const results = [];
  await Promise.all(Array.from({ length: Math.min(width, queue.length) }, async () => {
    while (queue.length) results.push(await run(queue.shift()));
  }));
  return results;
}

const started = Date.now();
const results = [...await pool(SHARED, jobs), ...await pool(ALONE, 1)];
console.log('# end-to-end files, wall time:');
for (const r of results) console.log(`#   ${r.seconds.padStart(6)} s  ${r.file}${r.ok ? '' : '  FAILED'}`);
console.log(`#   ${((Date.now() - started) / 1000).toFixed(1).padStart(6)} s  all`);
const ran = results.length === SHARED.length + ALONE.length;
if (!ran) console.error(`all.js: ${results.length} of ${SHARED.length + ALONE.length} files ran`);
process.exitCode = ran && results.every((r) => r.ok) ? 0 : 1;
