// End-to-end check that unsaved edits are not dropped without asking, in headless Chromium: with an edit to Robot
// not saved, "New frame" and "Rename" ask first, and declining keeps the edit. Started by
// org.kicnp.editor.EditorBrowserTest with EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as editor.e2e.mjs.
// Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch, password } from './browser.mjs';

let step = 'launch';

const role = 'input[aria-label="robotName role"]';
const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);
  const asked = [];
  page.on('dialog', (d) => { asked.push(d.message()); d.dismiss(); });

  step = 'log in, open Robot and edit a slot without saving';
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
  await page.locator('#tree [data-frame="Robot"]').click();
  await page.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  await page.fill(role, 'not saved yet');

  step = 'New frame asks before dropping the edit; declining keeps it';
  await page.click('#new-frame-button');
  check(asked.length === 1 && asked[0].includes('Robot'), 'New frame did not ask about the unsaved edit to Robot');
  check(await page.isVisible('#frame-panel'), 'the frame panel was left although the discard was declined');
  check(await page.inputValue(role) === 'not saved yet', 'the unsaved edit is gone');

  step = 'Rename asks before dropping the edit; declining keeps it';
  await page.click('#rename-button');
  check(asked.length === 2, 'Rename did not ask about the unsaved edit');
  check(await page.isHidden('#rename-form'), 'the rename form opened although the discard was declined');
  check(await page.inputValue(role) === 'not saved yet', 'the unsaved edit is gone');

  step = 'the edit saves';
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved Robot' }).waitFor();
  await page.screenshot({ path: join(artifacts, '13-unsaved-edits-kept.png') });
  console.log('edits e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('edits e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
