// End-to-end check of the semantic links drawn as arrows over the hierarchy, in headless Chromium, on the Table 5
// scenario's knowledge base. Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, ARTIFACTS and CHROMIUM
// as editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch } from './browser.mjs';

const problems = [];
let step = 'launch';

// Where an arrow starts and ends on screen, and the boxes of the frame buttons it is drawn between.
async function geometry(page, from, to, relation) {
  return page.evaluate(([f, t, r]) => {
    const p = [...document.querySelectorAll('#tree svg.link-layer path.link-arrow')]
      .find((x) => x.dataset.from === f && x.dataset.to === t && x.dataset.relation === r);
    if (!p) return null;
    const m = p.getScreenCTM();
    const at = (l) => {
      const q = p.getPointAtLength(l);
      return { x: m.a * q.x + m.c * q.y + m.e, y: m.b * q.x + m.d * q.y + m.f };
    };
    const box = (n) => document.querySelector('#tree .frame-button[data-frame="' + CSS.escape(n) + '"]')
      .getBoundingClientRect().toJSON();
    const tree = document.getElementById('tree').getBoundingClientRect();
    const b = p.getBoundingClientRect();
    return {
      start: at(0), end: at(p.getTotalLength()), drawnFrom: p.dataset.drawnFrom, drawnTo: p.dataset.drawnTo,
      fromBox: box(p.dataset.drawnFrom), toBox: box(p.dataset.drawnTo), classes: p.getAttribute('class'),
      marker: p.getAttribute('marker-end'), title: p.querySelector('title').textContent,
      stroke: getComputedStyle(p).stroke, dash: getComputedStyle(p).strokeDasharray,
      withinTree: b.right <= tree.right + 1 && b.left >= tree.left - 1
    };
  }, [from, to, relation]);
}

function near(point, box, what) {
  check(point.x >= box.right - 2 && point.x <= box.right + 10 && point.y >= box.top && point.y <= box.bottom,
    what + ' at ' + JSON.stringify(point) + ' is not on the right edge of its node ' + JSON.stringify(box));
}

async function arrowBetween(page, from, to, relation) {
  const g = await geometry(page, from, to, relation);
  check(g, 'no arrow ' + relation + ' ' + from + ' -> ' + to);
  near(g.start, g.fromBox, relation + ' ' + from + ' -> ' + to + ': the start');
  near(g.end, g.toBox, relation + ' ' + from + ' -> ' + to + ': the end');
  check(g.withinTree, relation + ' ' + from + ' -> ' + to + ' leaves the tree\'s box');
  check(g.marker === 'url(#arrowhead-' + relation.toLowerCase() + ')', 'the arrow has no arrowhead of its kind: ' + g.marker);
  return g;
}

const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));

  step = 'every link of the listing is an arrow';
  await page.goto(base);
  const tree = page.locator('#tree');
  await tree.locator('[data-frame="ScoutToCup"]').waitFor();
  await tree.locator('svg.link-layer path.link-arrow').first().waitFor({ state: 'attached' });
  const rows = await (await page.request.get(base + 'api/frames')).json();
  const expected = new Set(rows.flatMap((r) => r.links.map((l) => l.relation + ' ' + l.from + ' -> ' + l.to)));
  check(expected.size >= 10, 'the Table 5 listing has only ' + expected.size + ' links');
  const drawn = await page.$$eval('#tree path.link-arrow',
    (ps) => ps.map((p) => p.dataset.relation + ' ' + p.dataset.from + ' -> ' + p.dataset.to));
  check(drawn.length === expected.size && drawn.every((d) => expected.has(d)),
    'the arrows ' + JSON.stringify(drawn) + ' are not the listing\'s links ' + JSON.stringify([...expected]));
  check(await page.textContent('#link-count') === String(expected.size), 'the link list does not count every link');

  step = 'a succession, a synchronization and a restriction, each between its two nodes';
  const succession = await arrowBetween(page, 'ScoutToKitchen', 'ScoutToCup', 'SUCCESSION');
  check(succession.title.includes('succession: ScoutToKitchen → ScoutToCup'), 'the tooltip does not name it: ' + succession.title);
  check(succession.start.y < succession.end.y, 'the succession arrow does not go down from ScoutToKitchen to ScoutToCup');
  const sync = await arrowBetween(page, 'IntroducePino', 'PinoWalk', 'SYNCHRONIZATION');
  const restriction = await arrowBetween(page, 'ScoutServesCup', 'IntroduceAibo', 'RESTRICTION');
  await arrowBetween(page, 'AskUserName', 'Welcome', 'SUCCESSION');
  check(new Set([succession.stroke, sync.stroke, restriction.stroke]).size === 3, 'the relation kinds share a colour');
  check(new Set([succession.dash, sync.dash, restriction.dash]).size === 3, 'the relation kinds share a dash');
  check(await page.locator('#link-legend .link-swatch').count() === 4, 'the legend does not show the four kinds of arrow');

  step = 'a folded class: the link is drawn to its nearest visible ancestor';
  await tree.locator('[data-frame="Speech"]').focus();
  await page.keyboard.press('ArrowLeft');
  await tree.locator('[data-frame="IntroduceAibo"]').waitFor({ state: 'detached' });
  const folded = await geometry(page, 'ScoutServesCup', 'IntroduceAibo', 'RESTRICTION');
  check(folded && folded.drawnTo === 'Speech' && folded.classes.includes('via'),
    'the restriction into the folded IntroduceAibo is not drawn to Speech: ' + JSON.stringify(folded));
  near(folded.end, folded.toBox, 'the end of the folded restriction');
  check(folded.title.includes('Speech'), 'the tooltip does not say where the folded link is drawn: ' + folded.title);
  await page.keyboard.press('ArrowRight');
  await tree.locator('[data-frame="IntroduceAibo"]').waitFor();
  await arrowBetween(page, 'ScoutServesCup', 'IntroduceAibo', 'RESTRICTION');

  step = 'a filter that hides every link end lists the links instead';
  await page.fill('#search', 'PinoWalk');
  await page.waitForFunction(() => !document.querySelector('#tree [data-frame="ScoutToCup"]'));
  check(await page.locator('#tree path.link-arrow[data-from="ScoutToKitchen"]').count() === 0, 'an arrow is drawn to a filtered-out frame');
  check(await page.locator('#link-items li.not-drawn').count() > 0, 'links without a visible end are not marked in the list');
  await page.fill('#search', '');
  await tree.locator('[data-frame="ScoutToCup"]').waitFor();

  step = 'the link list works by keyboard and lights the arrow up';
  await page.locator('#link-list summary').focus();
  await page.keyboard.press('Enter');
  const item = page.locator('#link-items button.link-item[data-from="ScoutToKitchen"][data-to="ScoutToCup"]');
  await item.waitFor();
  await item.focus();
  check(await page.locator('#tree path.link-arrow.lit[data-from="ScoutToKitchen"][data-to="ScoutToCup"]').count() === 1,
    'focusing a link in the list does not light its arrow up');
  await page.keyboard.press('Enter');
  await page.locator('#frame-title', { hasText: 'ScoutToKitchen' }).waitFor();
  const hot = await page.$$eval('#tree path.link-arrow', (ps) => ps.map((p) => [p.classList.contains('hot'),
    p.dataset.from === 'ScoutToKitchen' || p.dataset.to === 'ScoutToKitchen']));
  check(hot.some(([h]) => h) && hot.every(([h, touches]) => h === touches),
    'exactly the opened frame\'s arrows should be highlighted: ' + JSON.stringify(hot));
  await arrowBetween(page, 'ScoutToKitchen', 'ScoutToCup', 'SUCCESSION');

  step = 'screenshot at 1280x800';
  await tree.locator('[data-frame="ScoutToCup"]').scrollIntoViewIfNeeded();
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(artifacts, '07-semantic-links.png') });

  step = 'arrows can be turned off and on';
  await page.locator('#show-links').focus();
  await page.keyboard.press('Space');
  check(await page.locator('#tree path.link-arrow').count() === 0, 'the arrows stay after unticking "arrows"');
  await page.keyboard.press('Space');
  check(await page.locator('#tree path.link-arrow').count() === expected.size, 'the arrows do not come back');

  step = 'a smaller window: the arrows follow the nodes';
  await page.setViewportSize({ width: 1024, height: 640 });
  await page.waitForTimeout(200);
  await arrowBetween(page, 'ScoutToKitchen', 'ScoutToCup', 'SUCCESSION');
  await arrowBetween(page, 'IntroducePino', 'PinoWalk', 'SYNCHRONIZATION');

  step = 'no console errors';
  check(problems.length === 0, problems.join('\n'));
  console.log('links e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('links e2e failed at step "' + step + '": ' + e.message);
  if (problems.length) console.error(problems.join('\n'));
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
