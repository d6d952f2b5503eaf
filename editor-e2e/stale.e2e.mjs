// End-to-end check of two people editing one frame, in headless Chromium: the page has unsaved edits to Robot
// when someone else saves Robot; "Revert" must then show Robot as it now is, not the revision read before.
// Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as
// editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch, password } from './browser.mjs';

let step = 'launch';

const role = 'input[aria-label="robotName role"]';
const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);

  step = 'log in, open Robot and edit a slot without saving';
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
  await page.locator('#tree [data-frame="Robot"]').click();
  await page.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  await page.fill(role, 'my unsaved role');

  step = 'someone else saves Robot';
  const headers = { Authorization: 'Bearer ' + password, 'Content-Type': 'application/json' };
  const robot = await (await fetch(base + 'api/frames/Robot')).json();
  robot.slots.find((s) => s.name === 'robotName').role = 'their saved role';
  const put = await fetch(base + 'api/frames/Robot', { method: 'PUT', headers,
    body: JSON.stringify(Object.assign(robot, { expectedRevision: robot.revision })) });
  check(put.ok, 'their save failed: ' + put.status + ' ' + await put.text());
  await page.locator('#stale-note').waitFor({ state: 'visible' });
  check((await page.textContent('#stale-note')).includes('Someone else changed Robot'), 'no warning about their change');

  step = 'Revert shows Robot as it now is';
  await page.click('#revert-button');
  for (const end = Date.now() + 5000; Date.now() < end && await page.inputValue(role) !== 'their saved role';) {
    await new Promise((r) => setTimeout(r, 100));
  }
  check(await page.inputValue(role) === 'their saved role' || await page.isVisible('#stale-note'),
    'after Revert the page shows the old revision ("' + await page.inputValue(role) + '") with no warning left');
  check(await page.inputValue(role) === 'their saved role', 'after Revert Robot shows "' + await page.inputValue(role)
    + '", not what was saved');

  step = 'an edit after the revert saves';
  await page.fill(role, 'my role after theirs');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved Robot' }).waitFor();
  await page.screenshot({ path: join(artifacts, '10-stale-revert.png') });
  console.log('stale e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('stale e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
