// End-to-end check that edits typed while a save is on its way are kept, in headless Chromium: the answer to the
// save is held back while another edit is typed; when it comes, the frame shows the saved revision, the later edit
// is still there and unsaved, and saving again stores it. Started by org.kicnp.editor.EditorBrowserTest with
// EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as editor.e2e.mjs.
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

  step = 'log in, open Robot and edit a slot';
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
  await page.locator('#tree [data-frame="Robot"]').click();
  await page.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  await page.fill(role, 'first, saved');

  step = 'save, and type another edit before the answer comes';
  let release;
  const held = new Promise((resolve) => { release = resolve; });
  let sent;
  const putSeen = new Promise((resolve) => { sent = resolve; });
  await page.route('**/api/frames/Robot', async (route) => {
    if (route.request().method() !== 'PUT') return route.continue();
    const response = await route.fetch(); // the server has saved; its answer waits
    sent();
    await held;
    await route.fulfill({ response });
  });
  await page.click('#save-button');
  await putSeen;
  await page.fill(role, 'second, typed during the save');
  release();
  await page.locator('#frame-notice', { hasText: 'Saved Robot' }).waitFor();

  step = 'the edit typed during the save is still there, unsaved';
  check(await page.inputValue(role) === 'second, typed during the save',
    'the answer to the save overwrote the later edit with "' + await page.inputValue(role) + '"');
  check(!(await page.isDisabled('#save-button')), 'Save is disabled although the later edit is not saved');
  check(await page.isHidden('#stale-note'), 'the page warns about a change by someone else after its own save: '
    + await page.textContent('#stale-note'));

  step = 'saving again stores it';
  await page.unroute('**/api/frames/Robot');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: /Saved Robot \(revision \d+\)\.$/ }).waitFor();
  check(await page.isDisabled('#save-button'), 'Save stays enabled after everything was saved');
  await page.screenshot({ path: join(artifacts, '15-edit-during-save-kept.png') });
  console.log('saving e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('saving e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
