// End-to-end check that every frame can be opened by its address, in headless Chromium: a frame named "world" (a
// legal frame name, and the World panel's address) opens from the address the page gives it, and #world still
// opens the World panel. Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, ARTIFACTS and CHROMIUM as
// editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch } from './browser.mjs';

const problems = [];
let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  page.setDefaultTimeout(10000);
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));

  step = 'open the frame named world from the tree; the page gives it an address';
  await page.goto(base);
  await page.locator('#tree [data-frame="world"]').click();
  await page.locator('#frame-title', { hasText: 'world' }).waitFor();
  const address = page.url();

  step = 'that address opens the frame named world, not the World panel';
  const again = await context.newPage();
  again.setDefaultTimeout(10000);
  again.on('pageerror', (e) => problems.push('page error: ' + e.message));
  await again.goto(address);
  await again.locator('#frame-title', { hasText: 'world' }).waitFor();
  check(await again.isVisible('#frame-panel'), 'the frame panel is not shown for ' + address);
  check(await again.isHidden('#world-panel'), 'the World panel opened for ' + address);
  await again.screenshot({ path: join(artifacts, '14-frame-named-world.png') });

  step = 'the same address in the old form (#NAME) still opens a frame, and #world the World panel';
  const old = await context.newPage();
  old.setDefaultTimeout(10000);
  await old.goto(base + '#Robot');
  await old.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  const world = await context.newPage();
  world.setDefaultTimeout(10000);
  await world.goto(base + '#world');
  await world.locator('#world-panel').waitFor({ state: 'visible' });

  step = 'no page errors';
  check(problems.length === 0, problems.join('\n'));
  console.log('address e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('address e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
