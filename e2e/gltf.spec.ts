import { readFileSync } from 'node:fs';
import { Document, NodeIO } from '@gltf-transform/core';
import { expect, test } from '@playwright/test';
import { readMeshAsync } from '../src/core/io/index.js';
import { buildMesh } from '../src/index.js';
import { addCube, addSphere, glbOf } from '../tests/io/gltf-fixtures.js';
import { appErrors, openApp, stats } from './helpers.js';


function scene(): Document {
  const document = new Document();
  addCube(document, 'Box');
  addSphere(document, 'Globe', 16, 8).setTranslation([3, 0, 0]);
  return document;
}

test.describe('glTF in the app', () => {
  test('opens a .glb welded to its surface, a .gltf with its .bin, refuses one without, and exports .glb', async ({ page }, testInfo) => {
    await openApp(page, 'cube.off');
    await page.locator('#file-input').setInputFiles({ name: 'scene.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from(await glbOf(scene())) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('scene.glb');
    // the cube's 24 and the sphere's 153 file vertices weld into 8 + 114, closed
    expect(await stats(page)).toMatchObject({ vertices: 122, faces: 236, boundaryLoops: 0 });
    await page.getByRole('tab', { name: 'File' }).click();
    await page.locator('#file-info summary', { hasText: 'Notes' }).click();
    await expect(page.locator('#file-info')).toContainText('welded 177 glTF vertices into 122');
    await expect(page.locator('#file-info')).toContainText('Globe: 114 vertices, 224 triangles');
    // the seams the file had cut open: the cube's 12 edges, the sphere's meridian (6) and pole edges (2 × 16)
    await expect(page.locator('#file-info')).toContainText('50 seam edges: where the file split its vertices');
    await page.getByRole('button', { name: 'Show the seams' }).click();
    await expect(page.getByRole('button', { name: 'Hide the seams' })).toHaveAttribute('aria-pressed', 'true');
    expect(await page.evaluate(() => window.halfedgeLab.state().seamsShown)).toBe(true);
    await expect(page.locator('#status')).toContainText('50 seam edges marked');
    await page.screenshot({ path: testInfo.outputPath('gltf-file-tab.png') });
    await page.getByRole('button', { name: 'Hide the seams' }).click();
    expect(await page.evaluate(() => window.halfedgeLab.state().seamsShown)).toBe(false);
    // an edit renumbers edges: the marks go, and asked again they are the edited mesh's (a cube
    // edge split in two is two seam edges; the new edges across its faces are none)
    expect(await page.evaluate(() => window.halfedgeLab.showSeams(true))).toBe(50);
    await page.evaluate(() => window.halfedgeLab.edit({ kind: 'split-edge', edge: 0 }));
    expect(await page.evaluate(() => window.halfedgeLab.state().seamsShown)).toBe(false);
    expect(await page.evaluate(() => window.halfedgeLab.showSeams(true))).toBe(51);
    await page.evaluate(() => window.halfedgeLab.undo());

    // a .gltf and its .bin, picked together
    const { json, resources } = await new NodeIO().writeJSON(scene(), { basename: 'scene' });
    const gltf = { name: 'scene.gltf', mimeType: 'model/gltf+json', buffer: Buffer.from(JSON.stringify(json)) };
    await page.locator('#file-input').setInputFiles([gltf, { name: 'scene.bin', mimeType: 'application/octet-stream', buffer: Buffer.from(resources['scene.bin']!) }]);
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('scene.gltf');
    expect((await stats(page)).vertices).toBe(122);
    // without it: the buffer is named, and the mesh on screen stays
    await page.locator('#file-input').setInputFiles(gltf);
    await expect(page.locator('#error-message')).toContainText("buffer 0 is the file 'scene.bin', which was not given");
    expect((await stats(page)).vertices).toBe(122);
    await page.getByRole('button', { name: 'Dismiss the error' }).click();

    // a meshopt-compressed file: its decoder loads in the worker when needed
    await page.locator('#file-input').setInputFiles({ name: 'packed.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from(await glbOf(scene(), 'meshopt')) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('packed.glb');
    expect(await stats(page)).toMatchObject({ vertices: 122, faces: 236 });
    // a Draco-compressed one: the decoder's script and WebAssembly load in the worker when needed
    await page.locator('#file-input').setInputFiles({ name: 'squeezed.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from(await glbOf(scene(), 'draco')) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('squeezed.glb');
    expect(await stats(page)).toMatchObject({ vertices: 122, faces: 236, boundaryLoops: 0 });
    await page.locator('#file-input').setInputFiles({ name: 'packed.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from(await glbOf(scene(), 'meshopt')) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('packed.glb');

    // out as .glb, and back: the same counts
    await expect(page.locator('#file-info')).toContainText('packed.glb — glTF binary (.glb), 175 vertices and 236 faces in the file');
    await page.getByRole('tab', { name: 'Operate' }).click();
    const downloading = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Export the mesh as glTF (.glb)' }).click();
    const download = await downloading;
    expect(download.suggestedFilename()).toBe('packed-edited.glb');
    const { mesh } = buildMesh((await readMeshAsync(readFileSync((await download.path())!))).soup);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual([122, 3 * 236 / 2, 236]);
    expect(appErrors(page)).toEqual([]);
  });

  test('opens a file again welding within a distance: a cube whose sides were written a hair apart closes', async ({ page }) => {
    await openApp(page, 'cube.off');
    const document = new Document();
    addCube(document, 'Box');
    const position = document.getRoot().listMeshes()[0]!.listPrimitives()[0]!.getAttribute('POSITION')!;
    position.setArray(Float32Array.from(position.getArray()! as Float32Array, (x, i) => (Math.floor(i / 12) % 2 ? x + 1e-5 : x)));
    await page.locator('#file-input').setInputFiles({ name: 'ajar.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from(await glbOf(document)) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('ajar.glb');
    expect(await stats(page)).toMatchObject({ vertices: 14 });
    expect((await stats(page)).boundaryLoops).toBeGreaterThan(0);

    await page.getByRole('tab', { name: 'File' }).click();
    await expect(page.locator('#file-info')).toContainText('Welded 24 glTF vertices into 14 (10 joined at equal positions');
    // a distance that is none: said, and the mesh stays
    await page.getByRole('spinbutton', { name: 'Weld distance' }).fill('-1');
    await page.getByRole('button', { name: 'Open again, welding within this distance' }).click();
    await expect(page.locator('#status')).toContainText('The weld distance must be a number of 0 or more');
    expect(await stats(page)).toMatchObject({ vertices: 14 });

    await page.getByRole('spinbutton', { name: 'Weld distance' }).fill('0.0001');
    await page.getByRole('spinbutton', { name: 'Weld distance' }).press('Enter');
    await expect.poll(async () => (await stats(page)).vertices).toBe(8);
    expect(await stats(page)).toMatchObject({ vertices: 8, edges: 18, faces: 12, boundaryLoops: 0 });
    await expect(page.locator('#file-info')).toContainText('Welded 24 glTF vertices into 8 (16 joined within 0.0001');
    expect(appErrors(page)).toEqual([]);
  });
});
