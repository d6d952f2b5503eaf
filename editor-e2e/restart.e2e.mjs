// End-to-end check of the page across a server restart, in headless Chromium.
// Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as
// editor.e2e.mjs. The page logs in and opens Robot; the script then writes ARTIFACTS/restart.request, the test
// restarts the server on the same port (sessions gone, Robot changed meanwhile) and writes ARTIFACTS/restart.done.
// Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { existsSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { artifacts, base, check, launch, password } from './browser.mjs';

const request = join(artifacts, 'restart.request');
const done = join(artifacts, 'restart.done');
let step = 'launch';

async function until(test, seconds, message) {
  for (const end = Date.now() + seconds * 1000; Date.now() < end;) {
    if (await test()) return;
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(message);
}

const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);

  step = 'log in and open Robot';
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
  await page.locator('#tree [data-frame="Robot"]').click();
  await page.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  check(await page.inputValue('input[aria-label="robotName role"]') === 'display name', 'Robot\'s role is not shown');

  step = 'the server restarts';
  writeFileSync(request, 'restart');
  await page.locator('#live.off').waitFor({ timeout: 20000 });
  await until(() => existsSync(done), 30, 'the test did not restart the server');
  await page.locator('#live:not(.off)').waitFor({ timeout: 20000 });

  step = 'after the restart the page asks for the login again';
  await page.locator('#login-form').waitFor({ state: 'visible', timeout: 5000 });
  check(await page.isHidden('#session-info'), 'the page still says it is logged in');
  check((await page.textContent('#readonly-note')).includes('Read-only until you log in'),
    'the read-only note is not shown: ' + await page.textContent('#readonly-note'));
  check(await page.isDisabled('#save-button'), 'Save is enabled without a login');

  step = 'the open frame shows what the server holds now';
  await until(async () => await page.inputValue('input[aria-label="robotName role"]') === 'changed while the page was away',
    5, 'Robot still shows the role from before the restart: ' + await page.inputValue('input[aria-label="robotName role"]'));
  await page.screenshot({ path: join(artifacts, '08-after-restart.png') });
  console.log('restart e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('restart e2e failed at step "' + step + '": ' + e.message);
} finally {
  rmSync(request, { force: true });
  rmSync(done, { force: true });
  await browser.close();
}
process.exit(failed ? 1 : 0);
