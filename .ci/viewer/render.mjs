#!/usr/bin/env node
// Renders a .glb in headless Chromium with three.js and checks the picture is not empty.
// Usage: node render.mjs <file.glb> <out.png>
// Exit 1 when the page reports an error (loader, WebGL) or < 1 % of the pixels differ from
// the background. Env: CHROMIUM (default /usr/bin/chromium).
import { createServer } from 'node:http';
import { readFile, writeFile } from 'node:fs/promises';
import { dirname, extname, join, normalize, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const [glbPath, outPath] = process.argv.slice(2);
if (!glbPath || !outPath) {
  console.error('usage: node render.mjs <file.glb> <out.png>');
  process.exit(2);
}
// VIEW=below looks up at the lower surface, where the mechanism hangs.
const VIEW_DIR = process.env.VIEW === 'below' ? '1, -0.7, 0.45' : '1, 0.8, 0.35';
const started = Date.now();
const fail = (msg) => {
  console.error(`render.mjs: FAIL: ${msg}`);
  process.exit(1); // playwright kills the browser it launched on exit
};
setTimeout(() => fail('timed out after 60 s'), 60_000).unref();

const WIDTH = 1280, HEIGHT = 720;
const BG = [0x1e, 0x23, 0x2b]; // background colour, sRGB 0-255
const MIN_FRACTION = 0.01;
const THREE_DIR = join(dirname(fileURLToPath(import.meta.url)), 'node_modules', 'three');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  // Playwright adds --headless and a fresh temporary --user-data-dir itself.
  '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  // WebGL without a GPU: ANGLE on SwiftShader (software Vulkan).
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

// The page: three.js from node_modules through an import map, the model at /model.glb.
// It sets window.__result to { error } or to a summary of what it rendered.
const PAGE = `<!doctype html>
<html><head><meta charset="utf-8"><link rel="icon" href="data:,">
<style>html, body { margin: 0; overflow: hidden; } canvas { display: block; }</style>
<script type="importmap">
{ "imports": { "three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/" } }
</script></head>
<body><canvas id="c" width="${WIDTH}" height="${HEIGHT}"></canvas>
<script>
window.report = (r) => { window.__result ??= r; };
// capture phase: also sees a module script that failed to load (three.js not served)
addEventListener('error', (e) => report({ error: 'page error: ' + (e.message ?? 'a script failed to load') }), true);
addEventListener('unhandledrejection', (e) => report({ error: 'page error: ' + (e.reason?.message ?? e.reason) }));
</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

async function main() {
  if (!document.createElement('canvas').getContext('webgl2')) {
    return report({ error: 'WebGL2 is unavailable in this browser (no GPU and no working SwiftShader?)' });
  }
  const canvas = document.getElementById('c');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setSize(${WIDTH}, ${HEIGHT}, false);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color().setRGB(${BG.map((c) => c / 255)}, THREE.SRGBColorSpace);

  let gltf;
  try {
    gltf = await new GLTFLoader().loadAsync('/model.glb');
  } catch (e) {
    return report({ error: 'GLTFLoader: ' + (e?.message ?? e) });
  }
  const model = gltf.scene;
  scene.add(model);

  // First animation, posed at the middle of its duration.
  const clip = gltf.animations[0];
  if (clip) {
    const mixer = new THREE.AnimationMixer(model);
    mixer.clipAction(clip).play();
    mixer.setTime(clip.duration / 2);
  }
  model.updateMatrixWorld(true);

  let meshes = 0;
  // Parts found by their report names: three.js strips '.' from node names, so each part
  // node carries its name in its extras, which GLTFLoader keeps as userData.
  let named = 0;
  let dotted = 0;
  model.traverse((o) => {
    if (o.isMesh && o.visible) meshes++;
    const part = o.userData?.flapwright_part;
    if (typeof part === 'string') { named++; if (part.includes('.')) dotted++; }
  });
  const box = new THREE.Box3().setFromObject(model);
  const center = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());
  const radius = box.isEmpty() ? 1 : Math.max(box.getBoundingSphere(new THREE.Sphere()).radius, 1e-6);

  // From above and behind: +x is aft, +y up, -z outboard (aircraft frame x aft, y outboard,
  // z up after the root's -90 deg about x); a little inboard for perspective.
  const fov = 35;
  const camera = new THREE.PerspectiveCamera(fov, ${WIDTH} / ${HEIGHT}, radius / 100, radius * 100);
  const dir = new THREE.Vector3(${VIEW_DIR}).normalize();
  const dist = radius / Math.sin(THREE.MathUtils.degToRad(fov / 2));
  camera.position.copy(center).addScaledVector(dir, dist);
  camera.lookAt(center);

  scene.add(new THREE.HemisphereLight(0xffffff, 0x445566, 1.5));
  const sun = new THREE.DirectionalLight(0xffffff, 2.5);
  sun.position.copy(camera.position).add(new THREE.Vector3(0, radius * 2, 0));
  sun.target.position.copy(center);
  scene.add(sun, sun.target);

  renderer.render(scene, camera);
  report({
    meshes,
    named,
    dotted,
    animation: clip ? { name: clip.name, duration: clip.duration, tracks: clip.tracks.length } : null,
    box: box.isEmpty() ? null : [box.min.toArray(), box.max.toArray()],
    gl: renderer.getContext().getParameter(renderer.getContext().VERSION),
  });
}
main().catch((e) => report({ error: 'page error: ' + (e?.stack ?? e) }));
</script></body></html>`;

const MIME = { '.js': 'text/javascript', '.html': 'text/html', '.glb': 'model/gltf-binary' };

async function handle(req, res) {
  const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  let body, type;
  try {
    if (path === '/') [body, type] = [PAGE, MIME['.html']];
    else if (path === '/model.glb') [body, type] = [glb, MIME['.glb']];
    else if (path.startsWith('/three/')) {
      const file = normalize(join(THREE_DIR, path.slice('/three/'.length)));
      if (!file.startsWith(THREE_DIR + sep)) throw new Error('outside three');
      [body, type] = [await readFile(file), MIME[extname(file)] ?? 'application/octet-stream'];
    }
  } catch {
    body = undefined;
  }
  if (body === undefined) {
    res.writeHead(404).end('not found');
    return;
  }
  res.writeHead(200, { 'content-type': type }).end(body);
}

// Runs in the page: the fraction of the PNG's pixels that differ from the background.
async function nonBackgroundFraction({ b64, bg }) {
  const img = new Image();
  img.src = 'data:image/png;base64,' + b64;
  await img.decode();
  const c = document.createElement('canvas');
  [c.width, c.height] = [img.width, img.height];
  const ctx = c.getContext('2d');
  ctx.drawImage(img, 0, 0);
  const d = ctx.getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) {
    const diff = Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]);
    if (diff > 12) n++;
  }
  return n / (d.length / 4);
}

const glb = await readFile(glbPath).catch((e) => fail(`cannot read ${glbPath}: ${e.message}`));
const server = createServer((req, res) => handle(req, res));
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const url = `http://127.0.0.1:${server.address().port}/`;

let browser;
try {
  browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS, timeout: 30_000 });
} catch (e) {
  fail(`cannot start ${CHROMIUM}: ${e.message.split('\n')[0]}`);
}
const page = await browser.newPage({ viewport: { width: WIDTH, height: HEIGHT } });
const problems = []; // what the browser says went wrong, for the message on failure
const details = () => problems.map((p) => `\n  ${p}`).join('');
page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
page.on('response', (r) => r.status() >= 400 && problems.push(`HTTP ${r.status()} ${r.url()}`));

await page.goto(url);
try {
  await page.waitForFunction(() => window.__result, null, { timeout: 40_000 });
} catch {
  fail(`the page never finished rendering${details() || ' (no error reported)'}`);
}
const result = await page.evaluate(() => window.__result);
if (result.error) fail(`${result.error}${details()}`);

const png = await page.locator('canvas').screenshot();
await writeFile(outPath, png);
const fraction = await page.evaluate(nonBackgroundFraction, { b64: png.toString('base64'), bg: BG });
await browser.close();
server.close();

console.log(`render.mjs: ${glbPath} -> ${outPath} (${WIDTH}x${HEIGHT}, ${((Date.now() - started) / 1000).toFixed(1)} s)`);
console.log(`  ${result.gl}`);
console.log(`  meshes=${result.meshes} animation=${result.animation ? `"${result.animation.name}" ${result.animation.tracks} tracks, posed at ${(result.animation.duration / 2).toFixed(3)} s of ${result.animation.duration.toFixed(3)} s` : 'none'}`);
console.log(`  bounding box (+Y up): ${JSON.stringify(result.box)}`);
console.log(`  parts with their report names in userData.flapwright_part: ${result.named} of ${result.meshes} meshes (${result.dotted} of those names with a '.')`);
if (result.named !== result.meshes) fail(`${result.meshes - result.named} meshes without their report name in userData.flapwright_part`);
console.log(`  non-background pixels: ${(fraction * 100).toFixed(2)} %`);
if (fraction < MIN_FRACTION) fail(`picture is empty: ${(fraction * 100).toFixed(2)} % < ${MIN_FRACTION * 100} % non-background pixels`);
