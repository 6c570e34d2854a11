#!/usr/bin/env node
// raylab view in a real browser: starts `RAYLAB view --port 0 ARGS...`, opens its page in headless
// Chromium (Debian's /usr/bin/chromium, driven by puppeteer-core, which never downloads a browser),
// does one check as a student would, saves a screenshot and stops the server.
//
// Usage: node tests/view/check_view.mjs --raylab PATH [--view-server RAYLAB_VIEW] --check refines|trace|tree|crash [--out DIR]
//          [--pixel X Y] [--expect TEXT]... [--expect-trace-error] [--expect-first-disagreement FUNCTION]
//          [--expect-agree] [--timeout SECONDS] -- SCENE [more options of raylab view]
// Prints PASS: lines with what it saw; on failure FAIL: lines, and exits 1. Every wait has a timeout
// (--timeout, 60 s by default) and the whole run takes at most 240 s.
// Install its one dependency first: npm ci --prefix tests/view
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const repository = path.resolve(here, '..', '..');
const CHROMIUM = '/usr/bin/chromium';
const WHOLE_RUN_SECONDS = 240;
const CHECKS = ['refines', 'trace', 'tree', 'crash'];
const STATE_WORDS = ['starting', 'rendering', 'stopped', 'done', 'failed', '启动中', '渲染中', '已停止', '完成', '失败'];

class Failure extends Error {}
const fail = (text) => { throw new Failure(text); };
const pass = (text) => console.log(`PASS: ${text}`);
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

function usage(problem) {
  console.log(`FAIL: ${problem}`);
  console.log('usage: node tests/view/check_view.mjs --raylab PATH --check refines|trace|tree|crash [--out DIR] ' +
              '[--pixel X Y] [--expect TEXT]... [--expect-trace-error] [--expect-first-disagreement FUNCTION] ' +
              '[--expect-agree] [--timeout SECONDS] -- SCENE [options of raylab view]');
  process.exit(1);
}

function parseArguments(args) {
  const o = { expect: [], timeout: 60, extra: [] };
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    const value = () => { if (i + 1 >= args.length) usage(`${a} needs a value`); return args[++i]; };
    if (a === '--') { o.extra = args.slice(i + 1); break; }
    else if (a === '--raylab') o.raylab = value();
    else if (a === '--view-server') o.viewServer = value();
    else if (a === '--check') o.check = value();
    else if (a === '--out') o.out = value();
    else if (a === '--pixel') { o.pixel = [Number(value()), Number(value())]; }
    else if (a === '--expect') o.expect.push(value());
    else if (a === '--expect-trace-error') o.expectTraceError = true;
    else if (a === '--expect-first-disagreement') o.expectFirstDisagreement = value();
    else if (a === '--expect-agree') o.expectAgree = true;
    else if (a === '--timeout') o.timeout = Number(value());
    else usage(`unknown option ${a}`);
  }
  if (!o.raylab) usage('--raylab PATH is missing');
  if (!CHECKS.includes(o.check)) usage(`--check must be one of ${CHECKS.join(', ')}`);
  if (o.extra.length === 0) usage('the scene is missing: put it after --');
  if (o.pixel && !o.pixel.every(Number.isInteger)) usage('--pixel needs two whole numbers');
  if (!(o.timeout > 0)) usage('--timeout needs a number of seconds');
  return o;
}

const options = parseArguments(process.argv.slice(2));
const WAIT_MS = options.timeout * 1000;
let server = null, serverExit = null, serverOutput = '';
let browser = null, page = null, userDataDir = null;
const pageErrors = [];

// ---- the server ----
function startServer() {
  // `raylab view` starts raylab-view beside it; a program built elsewhere (a test's renderer with a
  // planted mistake) is given to raylab-view itself (--view-server).
  const raylab = options.viewServer ? path.resolve(options.viewServer) : path.resolve(options.raylab);
  const args = options.viewServer ? ['--renderer', path.resolve(options.raylab), '--port', '0', ...options.extra]
                                  : ['view', '--port', '0', ...options.extra];
  console.log(`starting: ${raylab} ${args.join(' ')} (in ${repository})`);
  // A process group of its own, so that whatever it leaves running can be ended with it.
  server = spawn(raylab, args, { cwd: repository, stdio: ['ignore', 'pipe', 'pipe'], detached: true });
  return new Promise((resolve, reject) => {
    let line = '';
    const timer = setTimeout(() => reject(new Failure(
      `raylab view printed no address (http://127.0.0.1:PORT/) within ${options.timeout} s`)), WAIT_MS);
    const take = (chunk) => {
      const text = chunk.toString();
      serverOutput = (serverOutput + text).slice(-20000);
      line += text;
      const found = line.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (found) { clearTimeout(timer); resolve(found[0]); }
    };
    server.stdout.on('data', take);
    server.stderr.on('data', (chunk) => { serverOutput = (serverOutput + chunk.toString()).slice(-20000); });
    server.on('error', (e) => { clearTimeout(timer); reject(new Failure(`cannot start ${raylab}: ${e.message}`)); });
    server.on('exit', (code, signal) => {
      serverExit = signal ? `signal ${signal}` : `exit code ${code}`;
      clearTimeout(timer);
      reject(new Failure(`raylab view ended (${serverExit}) before printing its address`));
    });
  });
}

// SIGTERM, SIGKILL after 5 s; then any process it left behind in its group is killed too.
async function stopServer() {
  if (!server || !server.pid) return;
  if (!serverExit) {
    const ended = new Promise((resolve) => server.once('exit', resolve));
    server.kill('SIGTERM');
    const timer = setTimeout(() => { if (!serverExit) server.kill('SIGKILL'); }, 5000);
    await Promise.race([ended, sleep(7000)]);
    clearTimeout(timer);
  }
  try {
    process.kill(-server.pid, 0);
    console.log('note: raylab view left processes running after it ended; they are killed now');
    process.kill(-server.pid, 'SIGKILL');
  } catch { /* none left */ }
  server = null;
}

// ---- waiting ----
// Calls probe until it returns something truthy; fails naming what was awaited after the timeout.
async function waitFor(what, probe, ms = WAIT_MS) {
  const end = Date.now() + ms;
  let lastError = null;
  for (;;) {
    if (serverExit) fail(`raylab view ended (${serverExit}) while waiting for ${what}`);
    try {
      const result = await probe();
      if (result) return result;
    } catch (e) {
      if (e instanceof Failure) throw e;
      lastError = e;
    }
    if (Date.now() > end)
      fail(`timed out after ${Math.round(ms / 1000)} s waiting for ${what}` + (lastError ? ` (last error: ${lastError.message})` : ''));
    await sleep(200);
  }
}

// A GET from the page itself, with the page's header (the server refuses a trace without it):
// JSON, or {fetchError} when there was no answer.
const pageJson = (url, header = true) => page.evaluate(async (u, h) => {
  try {
    const r = await fetch(u, { cache: 'no-store', headers: h ? { 'X-Raylab-View': '1' } : {} });
    return r.ok ? await r.json() : { fetchError: `HTTP ${r.status}` };
  } catch (e) { return { fetchError: String(e) }; }
}, url, header);

async function status() {
  const s = await pageJson('/status');
  if (s.fetchError) throw new Error(`/status: ${s.fetchError}`);
  return s;
}

// The picture as it is shown now: its src, whether it has loaded at the status's size, and (take) its pixels.
const pictureNow = (take) => page.evaluate((take) => {
  const img = document.getElementById('picture');
  const result = { src: img.getAttribute('src') || '', complete: img.complete, width: img.naturalWidth, height: img.naturalHeight };
  if (take && img.complete && img.naturalWidth > 0) {
    const canvas = document.createElement('canvas');
    canvas.width = img.naturalWidth; canvas.height = img.naturalHeight;
    const context = canvas.getContext('2d');
    context.drawImage(img, 0, 0);
    result.pixels = Array.from(context.getImageData(0, 0, canvas.width, canvas.height).data);
  }
  return result;
}, take);

const versionOf = (src) => Number((src.match(/[?&]version=(\d+)/) || [])[1] || 0);

async function firstPicture() {
  const s = await waitFor('the status line', async () => {
    const text = await page.$eval('#status', (e) => e.innerText.trim()).catch(() => '');
    return text && /\d/.test(text) ? (await status()) : null;
  });
  const picture = await waitFor(`the first picture (#picture loaded at ${s.width}x${s.height})`, async () => {
    const p = await pictureNow(true);
    return p.src && p.complete && p.width === s.width && p.height === s.height ? p : null;
  });
  pass(`the first picture loaded: ${picture.src} (${picture.width}x${picture.height})`);
  return { s, picture };
}

async function visibleText() { return page.evaluate(() => document.body.innerText); }
async function count(selector) { return page.$$eval(selector, (list) => list.length); }
const shownSpp = async () => Number(((await page.$eval('#numbers', (e) => e.textContent)).match(/\d+(\.\d+)?/) || [])[0]);

// Clicks the picture at the centre of pixel (x, y) and waits for the trace's table or error.
async function clickPixel(s, x, y) {
  const box = await page.$eval('#overlay', (e) => { const r = e.getBoundingClientRect(); return { left: r.left, top: r.top, width: r.width, height: r.height }; });
  await page.mouse.click(box.left + (x + 0.5) * box.width / s.width, box.top + (y + 0.5) * box.height / s.height);
  const heading = await waitFor(`the trace's heading for pixel (${x}, ${y})`, () =>
    page.$eval('#trace', (e) => (e.querySelector('h2') || {}).textContent || '').then((t) => t.includes(`(${x}, ${y})`) && t));
  pass(`clicking the picture at pixel (${x}, ${y}) starts its trace: "${heading}"`);
  const outcome = await waitFor(`the trace of pixel (${x}, ${y}) (#trace-table tr.step or .trace-error)`, () => page.evaluate(() => {
    const error = document.querySelector('.trace-error');
    if (error) return { error: error.innerText };
    const rows = document.querySelectorAll('#trace-table tr.step').length;
    return rows > 0 ? { rows } : null;
  }));
  return outcome;
}

// ---- the checks ----
async function checkRefines() {
  const { picture: first } = await firstPicture();
  const firstSpp = await shownSpp();
  const firstVersion = versionOf(first.src);
  pass(`the status line shows: ${await page.$eval('#status', (e) => e.innerText.trim())}`);
  const second = await waitFor(`a later picture than version ${firstVersion}`, async () => {
    const s = await status();
    if (!(s.version > firstVersion)) return null;
    const p = await pictureNow(true);
    return p.src !== first.src && p.complete && p.width === s.width && versionOf(p.src) > firstVersion ? p : null;
  });
  pass(`a later picture loaded: ${second.src}`);
  const spp = await waitFor(`the samples per pixel shown to grow from ${firstSpp}`, async () => { const n = await shownSpp(); return n > firstSpp ? n : null; });
  pass(`the samples per pixel shown grew from ${firstSpp} to ${spp}`);
  let differing = 0;
  for (let i = 0; i < first.pixels.length; i++) if (first.pixels[i] !== second.pixels[i]) differing++;
  if (first.pixels.length !== second.pixels.length || differing === 0) fail('the two pictures have the same pixels: the picture did not refine');
  pass(`the two pictures differ in ${differing} of ${first.pixels.length} channel values`);
  const state = await page.$eval('#state', (e) => e.textContent.trim());
  if (!STATE_WORDS.includes(state)) fail(`the state word shown is "${state}", none of ${STATE_WORDS.join(', ')}`);
  pass(`the state word is shown: ${state}`);
}

async function checkTrace() {
  const { s } = await firstPicture();
  const [x, y] = options.pixel || [Math.floor(s.width / 2), Math.floor(s.height / 2)];
  const outcome = await clickPixel(s, x, y);
  if (outcome.error) {
    if (!options.expectTraceError) fail(`the trace of pixel (${x}, ${y}) failed: ${outcome.error}`);
    pass(`the trace of pixel (${x}, ${y}) shows an error, as expected: ${outcome.error}`);
    return;
  }
  if (options.expectTraceError) fail(`the trace of pixel (${x}, ${y}) shows a table, not the error expected`);
  const answer = await pageJson(`/trace?x=${x}&y=${y}`);
  if (answer.fetchError || !answer.ok) fail(`/trace?x=${x}&y=${y} fetched again: ${answer.fetchError || answer.error}`);
  const steps = (answer.steps || []).length, segments = (answer.segments || []).length;
  if (outcome.rows !== steps) fail(`the table has ${outcome.rows} step rows, /trace gave ${steps} steps`);
  pass(`the trace table has ${outcome.rows} step rows, as /trace has steps`);
  const lines = await count('#path-layer line.path-segment');
  if (lines < segments) fail(`the picture shows ${lines} path segments, /trace gave ${segments}`);
  pass(`the picture shows ${lines} path segments (/trace gave ${segments})`);
  if (await count('#path-layer circle.picked-pixel') < 1) fail('no marker (circle.picked-pixel) at the picked pixel');
  const firstRow = await page.$eval('#trace-table tr.first-disagreement', (e) => e.innerText).catch(() => null);
  if (options.expectFirstDisagreement) {
    if (firstRow === null) fail(`no first disagreement is marked (expected one at ${options.expectFirstDisagreement})`);
    if (!firstRow.includes(options.expectFirstDisagreement))
      fail(`the first disagreement marked does not mention ${options.expectFirstDisagreement}: ${firstRow.replace(/\s+/g, ' ')}`);
    pass(`the first disagreement is marked at ${options.expectFirstDisagreement}`);
  }
  if (options.expectAgree) {
    if (firstRow !== null) fail(`a first disagreement is marked, though every step should agree: ${firstRow.replace(/\s+/g, ' ')}`);
    pass('no first disagreement is marked: every step agrees');
  }
  if (answer.summary) pass(`the summary: ${answer.summary}`);
  // Another site's page cannot start a trace: without the page's header it is refused.
  const refused = await pageJson(`/trace?x=${x}&y=${y}`, false);
  if (refused.fetchError !== 'HTTP 403') fail(`a trace without the page's header was not refused: ${JSON.stringify(refused)}`);
  pass('a trace without the page\'s header is refused (HTTP 403)');
}

async function checkTree() {
  const s = await waitFor('status tree_levels > 1', async () => { const t = await status(); return t.tree_levels > 1 ? t : null; });
  pass(`the status has ${s.tree_levels} tree levels`);
  await firstPicture();
  await waitFor('#show-tree and #level to be enabled', () =>
    page.evaluate(() => !document.getElementById('show-tree').disabled && !document.getElementById('level').disabled));
  if (!(await page.$eval('#show-tree', (e) => e.checked))) await page.click('#show-tree');
  if (!(await page.$eval('#show-tree', (e) => e.checked))) fail('#show-tree is not checked after a click');
  await page.$eval('#level', (e) => {
    e.value = '2';
    e.dispatchEvent(new Event('input', { bubbles: true }));
    e.dispatchEvent(new Event('change', { bubbles: true }));
  });
  const tree = await pageJson('/tree');
  if (tree.fetchError) fail(`/tree: ${tree.fetchError}`);
  const expected = ((tree.levels || [])[2] || []).length;
  if (expected === 0) fail(`/tree has no boxes at level 2 (note: "${tree.note || ''}")`);
  const shown = await waitFor(`${expected} rect.tree-box at level 2`, async () => {
    const n = await count('#tree-layer rect.tree-box');
    return n === expected ? n : null;
  });
  pass(`level 2 shows ${shown} boxes, as /tree has: "${await page.$eval('#tree-count', (e) => e.textContent)}"`);
}

async function checkCrash() {
  const s = await waitFor('status state "failed"', async () => { const t = await status(); return t.state === 'failed' ? t : null; });
  pass(`the status says failed: ${s.message}`);
  const message = await waitFor('#message to be visible' + (options.expect.length ? ` with ${options.expect.map((t) => `"${t}"`).join(', ')}` : ''),
    () => page.evaluate((wanted) => {
      const e = document.getElementById('message');
      const text = e.innerText;
      const visible = !e.hidden && e.offsetParent !== null && getComputedStyle(e).display !== 'none' && text.trim() !== '';
      return visible && wanted.every((w) => text.includes(w)) ? text : null;
    }, options.expect));
  pass(`#message is visible: ${message}`);
  const failedShot = path.join(options.outDir, `${options.check}-failed.png`);
  await page.screenshot({ path: failedShot, fullPage: true });
  console.log(`screenshot of the failure: ${failedShot}`);
  const again = await status();
  pass(`/status still answers: state ${again.state}`);
  await waitFor('#continue to be enabled', () => page.$eval('#continue', (e) => !e.disabled));
  const response = page.waitForResponse((r) => new URL(r.url()).pathname === '/continue', { timeout: WAIT_MS });
  await page.click('#continue');
  const answer = await response.then((r) => r.text()).catch((e) => fail(`clicking #continue got no answer: ${e.message}`));
  pass(`clicking #continue got an answer: ${answer.trim()}`);
  const outcome = await clickPixel(again, Math.floor(again.width / 2), Math.floor(again.height / 2));
  pass(outcome.error ? `the trace shows an error: ${outcome.error}` : `the trace shows a table of ${outcome.rows} steps`);
}

async function checkExpectedTexts() {
  for (const text of options.expect) {
    await waitFor(`the page to show "${text}"`, async () => (await visibleText()).includes(text));
    pass(`the page shows "${text}"`);
  }
}

// The processes the server started and that still run (its renderer, a trace), from /proc.
function childrenOf(pid) {
  const children = [];
  try {
    for (const task of fs.readdirSync(`/proc/${pid}/task`)) {
      const text = fs.readFileSync(`/proc/${pid}/task/${task}/children`, 'utf8').trim();
      if (text) children.push(...text.split(/\s+/).map(Number));
    }
  } catch { /* the server is gone */ }
  return children;
}
const alive = (pid) => { try { process.kill(pid, 0); return true; } catch { return false; } };
let childrenAtEnd = [];

// ---- the run ----
async function cleanUp() {
  if (browser) await browser.close().catch(() => {});
  browser = null;
  await stopServer();
  if (userDataDir) fs.rmSync(userDataDir, { recursive: true, force: true });
}

async function main() {
  let puppeteer;
  try {
    puppeteer = (await import('puppeteer-core')).default;
  } catch (e) {
    fail(`puppeteer-core is not installed: run "npm ci" in ${here} (${e.message})`);
  }
  if (!fs.existsSync(CHROMIUM)) fail(`Chromium is not installed at ${CHROMIUM} (Debian's package chromium)`);
  const out = path.resolve(options.out || fs.mkdtempSync(path.join(os.tmpdir(), 'raylab-view-')));
  fs.mkdirSync(out, { recursive: true });
  options.outDir = out;
  console.log(`screenshots go to ${out}`);
  const address = await startServer();
  pass(`raylab view answers at ${address}`);
  userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'raylab-view-profile-'));
  browser = await puppeteer.launch({
    executablePath: CHROMIUM, headless: true, userDataDir, defaultViewport: { width: 1366, height: 900 },
    args: ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  page = await browser.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  page.setDefaultTimeout(WAIT_MS);
  await page.goto(address, { waitUntil: 'load', timeout: WAIT_MS });
  pass(`the page loaded: "${await page.title()}"`);
  try {
    if (options.check === 'refines') await checkRefines();
    else if (options.check === 'trace') await checkTrace();
    else if (options.check === 'tree') await checkTree();
    else await checkCrash();
    await checkExpectedTexts();
    if (pageErrors.length) fail(`the page's script threw: ${pageErrors.join(' | ')}`);
    childrenAtEnd = childrenOf(server.pid);
  } finally {
    const shot = path.join(out, `${options.check}.png`);
    await page.screenshot({ path: shot, fullPage: true }).then(() => console.log(`screenshot: ${shot}`), () => {});
  }
}

const wholeRun = setTimeout(async () => {
  console.log(`FAIL: the whole run took more than ${WHOLE_RUN_SECONDS} s`);
  await cleanUp();
  process.exit(1);
}, WHOLE_RUN_SECONDS * 1000);
for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, async () => { await cleanUp(); process.exit(1); });

let code = 0;
try {
  await main();
  pass(`check ${options.check}`);
} catch (e) {
  code = 1;
  console.log(`FAIL: ${e instanceof Failure ? e.message : `the check broke: ${e.stack || e}`}`);
  if (serverOutput.trim()) console.log(`raylab view printed (last lines):\n${serverOutput.trim().split('\n').slice(-20).join('\n')}`);
}
await cleanUp();
// What the server started must end with it (it kills its renderer's and a trace's process groups).
if (code === 0) {
  for (let i = 0; i < 50 && childrenAtEnd.some(alive); i++) await sleep(100);
  const left = childrenAtEnd.filter(alive);
  if (left.length) {
    code = 1;
    console.log(`FAIL: raylab view left ${left.length} of its processes running after it was stopped: ${left.join(', ')}`);
    for (const pid of left) { try { process.kill(pid, 'SIGKILL'); } catch { /* gone */ } }
  } else {
    pass(`no process of the ${childrenAtEnd.length} it had started is left`);
  }
}
clearTimeout(wholeRun);
process.exit(code);
