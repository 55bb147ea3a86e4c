// End-to-end tests of the lab in headless Chromium (SwiftShader): the error colouring with its HUD
// figures and shape histogram, the error-vs-resolution plot with its slopes, the live topology with
// pause_on=merge stopping the animation when the field's two blobs join, a subtracting sphere from a link, and the
// case tables: the decider's join on the CPU and the GPU, its notice, inspector and lecture section.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import {
  outputDir, useServerAndBrowser, openClosedAfterEach, openPanelGroups, settledTriangles, frameDrawn, screenshot, differingFraction,
} from './helpers.js';

useServerAndBrowser();

const open = openClosedAfterEach();

test('color_by=error colours the mesh, the HUD gives RMS and max error and a shape histogram, and the link carries it', async () => {
  // Spheres inside the box: where a wall cuts the solid, its cap sits up to a cell off the wall.
  const { page, errors } = await open('?balls=-0.25,0,0,0.3;0.2,0.1,0,0.28;0,-0.2,0.2,0.25&res=32&paused=1&hud=on&aa=0');
  await settledTriangles(page);
  const plain = await screenshot(page, 'lab-plain');
  await page.$eval('metaballs-view', (e) => e.setAttribute('color_by', 'error'));
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats.error !== null, null, { timeout: 20000 });
  const stats = await page.$eval('metaballs-view', (e) => e.stats);
  assert.ok(stats.error.rms > 0 && stats.error.rms < stats.error.max && stats.error.max < 1.5, JSON.stringify(stats.error));
  assert.equal(stats.quality.length, 10);
  assert.ok(stats.quality.reduce((a, b) => a + b, 0) >= stats.triangles * 0.9, `${stats.quality} against ${stats.triangles}`);
  assert.match(await page.textContent('#hud-error-text'), /^RMS [\d.e-]+ · max [\d.e-]+ cells$/);
  await frameDrawn(page);
  const coloured = await screenshot(page, 'lab-error');
  assert.ok(await differingFraction(page, plain, coloured) > 0.02, 'the error colouring changes the picture');
  assert.match(page.url(), /color_by=error/);
  // Midpoint placement sits further off the surface.
  await page.$eval('metaballs-view', (e) => e.setAttribute('interpolation', 'midpoint'));
  await page.waitForFunction((linear) => (document.querySelector('metaballs-view').stats.error?.rms ?? 0) > 4 * linear,
    stats.error.rms, { timeout: 20000 }).catch(async (e) => {
    console.log('linear', stats.error, 'now', await page.$eval('metaballs-view', (f) => [f.stats.error, f.interpolation]));
    throw e;
  });
  assert.deepEqual(errors, []);
});

test('the error plot sweeps the resolutions off the frame loop and shows second and first order slopes', async () => {
  const balls = '-0.25,0,0,0.3;0.2,0.1,0,0.28;0,-0.2,0.2,0.25';
  const { page, errors } = await open(`?balls=${balls}&res=32&paused=1&controls=all`);
  await settledTriangles(page);
  await page.click('text=Teaching');
  await page.click('#error-plot');
  await page.waitForSelector('figure.error-plot svg', { timeout: 120000 });
  const caption = await page.textContent('figure.error-plot figcaption');
  const slope = (name, key) => Number(new RegExp(`${name}: RMS slope (-?[\\d.]+), max slope (-?[\\d.]+)`).exec(caption)[key === 'rms' ? 1 : 2]);
  assert.ok(slope('linear', 'rms') < -1.6 && slope('linear', 'rms') > -2.6, caption);
  assert.ok(slope('midpoint', 'rms') < -0.7 && slope('midpoint', 'rms') > -1.35, caption);
  assert.match(await page.getAttribute('figure.error-plot svg', 'aria-label'), /log-log/);
  assert.deepEqual(errors, []);
});

test('pause_on=merge stops the animation at the frame the field\'s two blobs become one, and says so', async () => {
  // Two spheres flying at each other.
  const balls = '-0.5,0,0,0.2,0.6,0,0;0.5,0,0,0.2,-0.6,0,0';
  const { page, errors } = await open(`?balls=${balls}&res=32&pause_on=merge&hud=on&mesher=cpu`);
  // The HUD says so while they are apart (read in the same moment as the statistics: they may touch soon after).
  const apart = await page.waitForFunction(() => {
    const view = document.querySelector('metaballs-view');
    return view.stats.topology?.components === 2 && view.shadowRoot.getElementById('hud-topology-text').textContent;
  }, null, { timeout: 30000 });
  assert.match(await apart.jsonValue(), /^2 blobs · genus 0 · closed manifold$/);
  await page.waitForFunction(() => document.querySelector('metaballs-view').paused, null, { timeout: 60000 });
  assert.match(await page.$eval('metaballs-view', (e) => e.shadowRoot.getElementById('announce').textContent),
    /2 blobs → 1, paused where the field joins them \(f = [\d.]+ at the saddle\)/);
  // Paused at the first frame the field has one blob: its saddle is just above the iso level (1).
  const field = await page.$eval('metaballs-view', (e) => e.criticalPoints());
  assert.equal(field.counts.blobs, 1);
  const saddle = field.points.find((p) => p.role === 'join');
  assert.ok(saddle.value > 1 && saddle.value < 1.1, `the saddle at the pause: f = ${saddle.value}`);
  assert.deepEqual(errors, []);
});

test('a change of table that changes no cell says so, naming what each table would change', async () => {
  const { page, errors } = await open('?balls=0.05,0.02,0,0.4&res=24&paused=1');
  await settledTriangles(page);
  const notice = (table) => page.$eval('metaballs-view', (e, t) => e.setAttribute('table', t), table)
    .then(() => page.waitForFunction((t) => {
      const text = document.querySelector('metaballs-view').shadowRoot.getElementById('notice').textContent;
      return text.startsWith(`table=${t}:`) && text;
    }, table, { timeout: 30000 }))
    .then((handle) => handle.jsonValue());
  assert.equal(await notice('mc33'), 'table=mc33: no cell here has a face the asymptotic decider joins or a tunnel MC33 draws; both tables give this mesh');
  assert.equal(await notice('decider'), 'table=decider: no cell here has a tunnel MC33 draws; both tables give this mesh');
  assert.equal(await notice('classic'), 'table=classic: no cell here has a face the asymptotic decider joins; both tables give this mesh');
  assert.deepEqual(errors, []);
});

test('a negative radius in the link subtracts a sphere, and the editor toggles it', async () => {
  const { page, errors } = await open('?balls=-0.3,0,0,0.4&res=48&paused=1&edit=on');
  const whole = await settledTriangles(page);
  const before = await screenshot(page, 'lab-whole');
  await page.$eval('metaballs-view', (e) => e.setAttribute('balls', '-0.3,0,0,0.4;0.4,0,0,-0.3'));
  const dented = await settledTriangles(page);
  assert.notEqual(dented, whole);
  assert.equal(await page.$eval('metaballs-view', (e) => e.sphereList[1].charge), -1);
  assert.ok(await differingFraction(page, before, await screenshot(page, 'lab-dented')) > 0.01, 'the dent shows');
  // The editor's Subtract button adds the sphere back, and the list says so.
  await page.$eval('metaballs-view', (e) => e.shadowRoot.getElementById('view').focus());
  const at = await page.$eval('metaballs-view', (e) => e.sphereOnScreen(1));
  await page.mouse.click(at.x, at.y);
  assert.equal(await page.$eval('metaballs-view', (e) => e.selectedSphere), 1);
  await page.click('#sphere-charge');
  await page.waitForFunction(() => document.querySelector('metaballs-view').sphereList[1].charge === 1);
  assert.deepEqual(errors, []);
});

test('table=decider joins the two blobs the interpolant joins, on the CPU and the GPU, from the panel and the link', async () => {
  // Seed 11, 64 spheres, 128³, iso 1.5: the classic table makes 58 blobs where the field's interpolant
  // has 57 (scikit-image's Lewiner method agrees).
  const { page, errors } = await open('?seed=11&spheres=64&res=128&iso=1.5&paused=1&mesher=cpu&controls=all&aa=0');
  await settledTriangles(page);
  const shape = () => page.$eval('metaballs-view', async (e) => [(await e.topology()).components, e.stats.triangles]);
  assert.deepEqual(await shape(), [58, 54404]);
  await openPanelGroups(page);
  await page.selectOption('#table', 'decider');
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats.triangles === 54408, null, { timeout: 30000 });
  assert.deepEqual(await shape(), [57, 54408]);
  await page.waitForFunction(() => location.search.includes('table=decider'), null, { timeout: 30000 });
  // A notice names the cells that changed and says how the blob count went.
  const told = (table) => page.waitForFunction((t) => {
    const text = document.querySelector('metaballs-view').shadowRoot.getElementById('notice').textContent;
    return text.startsWith(`table=${t}:`) && text;
  }, table, { timeout: 30000 }).then((handle) => handle.jsonValue());
  const decided = await told('decider');
  assert.match(decided, /^table=decider: \d+ cells? changed, each with a face the decider joins and the classic table cuts: \(\d+, \d+, \d+\)/);
  assert.match(decided, /blobs 58 → 57$/);
  // The inspector shows the cell's ambiguous face: its saddle, the decider's choice, the joining drawn.
  const cell = decided.match(/\((\d+), (\d+), (\d+)\)/).slice(1).map(Number);
  const report = await page.$eval('metaballs-view', (e, c) => e.inspectCell(...c), cell);
  assert.ok(report.faces.some((f) => f.deciderJoins && f.joined && f.saddle > 1.5), JSON.stringify(report.faces));
  const faces = () => page.$eval('metaballs-view', (e) => e.shadowRoot.querySelector('#inspector .faces').textContent);
  assert.match(await faces(), /saddle [\d.]+ > 1\.50: the decider joins its inside corners; drawn joined/);
  // Beside the triangles, the cell's trilinear interpolant, ray cast: a surface with both sides in view.
  const drawn = await page.$eval('metaballs-view', (e) => {
    const canvas = e.shadowRoot.querySelector('#inspector canvas.interpolant');
    const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    let [outside, inside] = [0, 0];
    for (let k = 0; k < data.length; k += 4) {
      // The surface's two sides as lit: the mesh's salmon outside, teal inside (not the orange and blue
      // corner dots, nor the grey edges).
      const [r, g, b] = [data[k], data[k + 1], data[k + 2]];
      if (r > 90 && r > 1.6 * g && b < g && b > 0.6 * g) outside += 1;
      if (g > 60 && g > 1.4 * r && b > 1.3 * r && b < 1.1 * g) inside += 1;
    }
    return { outside, inside, label: canvas.getAttribute('aria-label') };
  });
  assert.ok(drawn.outside > 200 && drawn.inside > 200, JSON.stringify(drawn));
  assert.match(drawn.label, /trilinear interpolant/);
  // The GPU's compute passes make the same mesh.
  await page.$eval('metaballs-view', (e) => e.setAttribute('mesher', 'gpu'));
  await page.waitForFunction(() => {
    const { stats } = document.querySelector('metaballs-view');
    return stats.mesher === 'gpu' && stats.triangles === 54408;
  }, null, { timeout: 30000 });
  assert.deepEqual(await shape(), [57, 54408]);
  // A question about the shape still on its way when the table changes answers for the mesh it was
  // asked about; one asked after the new mesh is drawn answers for that one.
  await page.$eval('metaballs-view', (e) => { window.earlier = e.topology(); });
  await page.selectOption('#table', 'classic');
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats.triangles === 54404, null, { timeout: 30000 });
  assert.deepEqual(await shape(), [58, 54404]);
  assert.equal(await page.evaluate(() => window.earlier.then((s) => s.components)), 57);
  assert.match(await told('classic'), /cells? changed.*blobs 57 → 58$/);
  // Under the classic table the inspected face is cut apart, against the decider: marked.
  await page.$eval('metaballs-view', (e, c) => e.inspectCell(...c), cell);
  assert.match(await faces(), /the decider joins its inside corners; drawn cut apart \(against the decider\)/);
  assert.equal(await page.$eval('metaballs-view', (e) => e.shadowRoot.querySelectorAll('#inspector .faces .disagrees').length > 0), true);
  await page.selectOption('#table', 'decider');
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats.triangles === 54408, null, { timeout: 30000 });
  assert.match(await told('decider'), /blobs 58 → 57$/);
  // A bad value keeps the table in use and says what is accepted.
  await page.$eval('metaballs-view', (e) => e.setAttribute('table', 'mc99'));
  const notice = await page.waitForFunction(() => {
    const text = document.querySelector('metaballs-view').shadowRoot.getElementById('notice').textContent;
    return text.includes('mc99') && text;
  }, null, { timeout: 30000 }).then((handle) => handle.jsonValue());
  assert.ok(notice.includes('classic, decider'), notice);
  assert.equal(await page.evaluate(() => document.querySelector('metaballs-view').table), 'decider');
  assert.deepEqual(errors, []);
});

// The lecture's figures in `figure#id`, drawn: their selector, and each one's table and blob count.
async function lectureFigures(id) {
  const { page, errors } = await open('www/examples/lecture.html');
  await page.locator(`figure#${id}`).scrollIntoViewIfNeeded();
  const figures = `figure#${id} metaballs-view`;
  await page.waitForFunction((s) => [...document.querySelectorAll(s)].every((e) => e.framesDrawn > 1), figures, { timeout: 60000 });
  const shapes = await page.$$eval(figures, (views) => Promise.all(views.map(async (e) => [e.table, (await e.topology()).components])));
  return { page, errors, figures, shapes };
}

test('the lecture shows two touching spheres apart under the classic table and joined under the decider', async () => {
  const { page, errors, figures, shapes } = await lectureFigures('ambiguity');
  assert.deepEqual(shapes, [['classic', 2], ['decider', 1]]);
  // The ambiguous face's joining: red where the classic table cuts what the decider joins, amber where
  // the triangles follow the decider.
  const colours = [];
  for (const [k, view] of (await page.$$(figures)).entries()) {
    const shot = await view.screenshot({ path: path.join(outputDir, `e2e-lecture-ambiguity-${k}.png`) });
    colours.push(await page.evaluate(async (png) => {
      const image = await createImageBitmap(new Blob([new Uint8Array(png)], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(image.width, image.height);
      const context = canvas.getContext('2d');
      context.drawImage(image, 0, 0);
      const data = context.getImageData(0, 0, image.width, image.height).data;
      let [red, amber] = [0, 0];
      for (let i = 0; i < data.length; i += 4) {
        if (data[i] > 200 && data[i + 1] < 40 && data[i + 2] < 40) red += 1;
        if (data[i] > 200 && data[i + 1] > 130 && data[i + 1] < 215 && data[i + 2] < 60) amber += 1;
      }
      return { red, amber };
    }, [...shot]));
  }
  assert.ok(colours[0].red > 0 && colours[0].amber === 0, `classic: ${JSON.stringify(colours[0])}`);
  assert.ok(colours[1].red === 0 && colours[1].amber > 0, `decider: ${JSON.stringify(colours[1])}`);
  assert.deepEqual(errors, []);
});

test('the lecture shows two spheres on a cell\'s body diagonal joined only under MC33, with the tunnel in the inspector', async () => {
  const { page, errors, figures, shapes } = await lectureFigures('interior');
  assert.deepEqual(shapes, [['classic', 2], ['decider', 2], ['mc33', 1]]);
  // The cell between the spheres: the interpolant joins corners 0 and 6 through it; a tunnel is drawn
  // only under MC33, and its triangles join the two loops (four more than their two fills).
  const reports = await page.$$eval(figures, (views) => views.map((e) => e.inspectCell(4, 4, 4)));
  assert.deepEqual(reports.map((r) => [r.interior, r.tunnel, r.triangles.length]), [[[0, 6], false, 2], [[0, 6], false, 2], [[0, 6], true, 6]]);
  // MC33's configuration 4.1.2 in every figure; the other two tables draw 4.1.1.
  assert.deepEqual(reports.map((r) => [r.subcase, r.drawnSubcase]), [['4.1.2', '4.1.1'], ['4.1.2', '4.1.1'], ['4.1.2', '4.1.2']]);
  const said = await page.$eval('figure#interior metaballs-view:last-of-type', (e) => e.shadowRoot.querySelector('#inspector .interior').textContent);
  assert.match(said, /joins corners 0 and 6 through a saddle; drawn as a tunnel \(table=mc33\)/);
  // Switching the decider's figure to MC33 names the cell that changed: the tunnel joins the blobs.
  await page.$eval('figure#interior metaballs-view:nth-of-type(2)', (e) => e.setAttribute('table', 'mc33'));
  const notice = await page.waitForFunction(() => {
    const text = document.querySelector('figure#interior metaballs-view:nth-of-type(2)').shadowRoot.getElementById('notice').textContent;
    return text.startsWith('table=mc33:') && text;
  }, null, { timeout: 30000 }).then((handle) => handle.jsonValue());
  assert.equal(notice, 'table=mc33: 1 cell changed, each with a tunnel through its inside that MC33 draws: (4, 4, 4); blobs 2 → 1');
  // The statistics follow: one blob, with nothing more drawn after the change.
  await page.waitForFunction(() => document.querySelector('figure#interior metaballs-view:nth-of-type(2)').shadowRoot
    .getElementById('hud-topology-text').textContent.startsWith('1 blob ·'), null, { timeout: 10000 });
  assert.deepEqual(errors, []);
});

test('changing the table under surface nets says the mesh keeps the classic table', async () => {
  const { page, errors } = await open('?res=32&method=surface_nets&paused=1');
  await settledTriangles(page);
  const triangles = await page.$eval('metaballs-view', (e) => e.stats.triangles);
  await page.$eval('metaballs-view', (e) => e.setAttribute('table', 'decider'));
  await page.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot.getElementById('notice')
    .textContent === 'table=decider: surface nets keeps the classic table; the mesh is unchanged', null, { timeout: 10000 });
  await frameDrawn(page);
  assert.equal(await page.$eval('metaballs-view', (e) => e.stats.triangles), triangles);
  assert.deepEqual(errors, []);
});
