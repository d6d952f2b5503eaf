// End-to-end check of the World panel of an editor that is not connected to a platform, in headless Chromium.
// Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, ARTIFACTS and CHROMIUM as editor.e2e.mjs.
// Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch } from './browser.mjs';

const problems = [];
let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));

  step = 'open the World panel by its address';
  await page.goto(base + '#world');
  await page.locator('#world-panel').waitFor({ state: 'visible' });

  step = 'every part says it is not connected';
  for (const id of ['world-off', 'chat-off', 'teleop-off']) {
    await page.locator('#' + id).waitFor({ state: 'visible' });
    check((await page.textContent('#' + id)).includes('Not connected to a platform'), id + ' does not say so in words');
  }
  for (const id of ['world-view', 'chat-box', 'teleop-box']) check(await page.isHidden('#' + id), id + ' is shown without a platform');
  check((await page.textContent('#world-meta')).includes('not connected'), 'the panel heading does not say it is not connected');
  await page.screenshot({ path: join(artifacts, '06-world-not-connected.png') });

  step = 'no console errors';
  check(problems.length === 0, problems.join('\n'));
  console.log('world offline e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('world offline e2e failed at step "' + step + '": ' + e.message);
  if (problems.length) console.error(problems.join('\n'));
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
