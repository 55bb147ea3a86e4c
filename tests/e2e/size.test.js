// The page's WebAssembly within its download budgets, gzipped as `www/build.sh` and the benchmarks
// report it (`gzip -9`), in kilobytes of 1,000 bytes: the WebGPU build, which nearly every visitor
// loads, at most 200 KB; the WebGL2 build, loaded only where WebGPU is missing, at most 900 KB. Both
// are read as `www/build.sh` left them: a build that is missing fails here rather than passing
// unmeasured.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { root } from './helpers.js';

const BUDGETS = [
  { build: 'pkg', api: 'WebGPU', budget: 200_000 },
  { build: 'pkg-webgl', api: 'WebGL2', budget: 900_000 },
  // The critical points' module, fetched only by a figure that shows them.
  { build: 'pkg-levels', api: 'critical points', budget: 70_000, file: 'metaballs_levels_bg.wasm' },
];

for (const { build, api, budget, file: name = 'metaballs_bg.wasm' } of BUDGETS) {
  test(`the ${api} build's wasm is at most ${budget} bytes gzipped`, () => {
    const file = path.join(root, build, name);
    let bytes;
    try {
      bytes = readFileSync(file);
    } catch (error) {
      assert.fail(`${path.relative(root, file)} cannot be read (${error.code}): build it with bash www/build.sh`);
    }
    assert.deepEqual([...bytes.subarray(0, 4)], [0x00, 0x61, 0x73, 0x6d], `${build}/${name} is not WebAssembly`);
    const gzipped = execFileSync('gzip', ['-9c', file], { maxBuffer: 64 << 20 }).length;
    console.log(`${build}/${name}: ${bytes.length} bytes, ${gzipped} gzipped (budget ${budget})`);
    assert.ok(gzipped <= budget,
      `${build}/${name} is ${gzipped} bytes gzipped, ${gzipped - budget} over its budget of ${budget}`);
  });
}
