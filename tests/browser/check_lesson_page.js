// SPDX-License-Identifier: MIT
// Loads a lesson page (collide lesson) from disk in headless Chromium and checks it as a reader's
// browser shows it, at each width given: the video reaches readyState 4 and plays, its caption
// track has as many cues as the .vtt beside it, every image loads, every MathML element lays out
// with a size, nothing is wider than the window, and axe-core finds no accessibility violation.
// Usage: node check_lesson_page.js MODULES_DIR CHROMIUM PAGE LANG DIR WIDTH... [--shots OUT_PREFIX]
// Prints one line per check; exits 1 if any fails.
'use strict';
const fs = require('fs');
const path = require('path');

const [modules, chromium, page_path, lang, dir, ...rest] = process.argv.slice(2);
const shots_at = rest.indexOf('--shots');
const shots = shots_at >= 0 ? rest[shots_at + 1] : null;
const widths = (shots_at >= 0 ? rest.slice(0, shots_at) : rest).map(Number);
const puppeteer = require(path.join(modules, 'puppeteer-core'));
const axe_source = path.join(modules, 'axe-core', 'axe.min.js');

let failed = 0;
function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  if (!ok) failed = 1;
}

// The cues of the .vtt the page links, counted in the file: one "-->" line each.
function vttCues() {
  const vtt = fs.readFileSync(path.join(path.dirname(page_path), 'video.vtt'), 'utf8');
  return vtt.split('\n').filter((line) => line.includes('-->')).length;
}

// Runs in the page: waits (bounded) for the video and its track, then reports what it found.
async function inspect() {
  const wait = (ms) => new Promise((done) => setTimeout(done, ms));
  const video = document.querySelector('video');
  const until = Date.now() + 15000;
  while (video.readyState < 4 && Date.now() < until) await wait(25);
  const track = video.textTracks[0];
  while (track && (!track.cues || track.cues.length === 0) && Date.now() < until) await wait(25);
  let played = false;
  try {
    video.muted = true;
    await video.play();
    played = !video.paused;
    video.pause();
  } catch (error) {
    played = String(error);
  }
  const images = [...document.images].map((img) => ({
    src: img.getAttribute('src'), loaded: img.complete && img.naturalWidth > 0,
    alt: img.getAttribute('alt') || ''}));
  const maths = [...document.querySelectorAll('math')].map((m) => {
    const box = m.getBoundingClientRect();
    return box.width > 0 && box.height > 0;
  });
  return {
    ready: video.readyState, played, src: video.currentSrc,
    cues: track && track.cues ? track.cues.length : 0, track_mode: track ? track.mode : null,
    images, maths, lang: document.documentElement.lang, dir: document.documentElement.dir,
    scroll_width: document.documentElement.scrollWidth, window_width: window.innerWidth,
  };
}

async function checkWidth(browser, width) {
  const page = await browser.newPage();
  await page.setViewport({width, height: width > 600 ? 900 : 740});
  await page.goto('file://' + path.resolve(page_path), {waitUntil: 'load'});
  const found = await page.evaluate(inspect);
  const at = ` (${width} px)`;
  check(found.lang === lang && found.dir === dir, `lang=${found.lang} dir=${found.dir}` + at);
  check(found.ready === 4, `video readyState ${found.ready}, ${path.basename(found.src)}` + at);
  check(found.played === true, `video plays: ${found.played}` + at);
  const expected = vttCues();
  check(found.cues === expected, `caption track: ${found.cues} cues of ${expected}` + at);
  for (const image of found.images) {
    check(image.loaded && image.alt.length > 0, `image ${image.src} loads, has alt text` + at);
  }
  check(found.maths.every(Boolean), `${found.maths.length} MathML elements lay out` + at);
  check(found.scroll_width <= found.window_width,
        `page ${found.scroll_width} px wide in a ${found.window_width} px window` + at);
  await page.addScriptTag({path: axe_source});
  const axe = await page.evaluate(async () => {
    const result = await window.axe.run(document);
    return result.violations.map((v) => `${v.id}: ${v.help} (${v.nodes.length})`);
  });
  check(axe.length === 0, 'axe-core: ' + (axe.length ? axe.join('; ') : 'no violations') + at);
  if (shots) {
    await page.screenshot({path: `${shots}-${width}.png`, fullPage: true});
  }
  await page.close();
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: chromium, headless: true,
    args: ['--no-sandbox', '--mute-audio', '--autoplay-policy=no-user-gesture-required',
           '--disable-gpu', '--no-first-run'],
  });
  try {
    for (const width of widths) await checkWidth(browser, width);
  } finally {
    await browser.close();
  }
  process.exit(failed);
})().catch((error) => {
  console.log('FAIL ' + error);
  process.exit(1);
});
