// End-to-end check of a login that ends while the page is open, in headless Chromium: page A has unsaved edits
// to Robot when page B (same browser, same session cookie) logs out. A's save is refused; the page must then offer
// the login again, keep the edit, and save it after the login. Started by org.kicnp.editor.EditorBrowserTest with
// EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as editor.e2e.mjs. Exits 0 when every step passed.
import { join } from 'node:path';
import { artifacts, base, check, launch, password } from './browser.mjs';

let step = 'launch';

const role = 'input[aria-label="robotName role"]';
const browser = await launch();
let failed = false;
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const a = await context.newPage();
  a.setDefaultTimeout(10000);

  step = 'page A logs in, opens Robot and edits a slot';
  await a.goto(base);
  await a.locator('#live:not(.off)').waitFor();
  await a.fill('#login-password', password);
  await a.click('#login-button');
  await a.locator('#session-info').waitFor({ state: 'visible' });
  await a.locator('#tree [data-frame="Robot"]').click();
  await a.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  await a.fill(role, 'kept across the login');

  step = 'page B logs out';
  const b = await context.newPage();
  await b.goto(base);
  await b.locator('#session-info').waitFor({ state: 'visible' });
  await b.click('#logout-button');
  await b.locator('#login-form').waitFor({ state: 'visible' });

  step = 'page A saves: refused, and the page offers the login again';
  await a.click('#save-button');
  await a.locator('#frame-errors').waitFor({ state: 'visible' });
  check((await a.textContent('#frame-errors')).includes('Log in'), 'the refusal does not say to log in');
  await a.locator('#login-form').waitFor({ state: 'visible', timeout: 3000 });
  check(await a.isHidden('#session-info'), 'page A still says it is logged in');
  check(await a.inputValue(role) === 'kept across the login', 'the unsaved edit was lost');

  step = 'after logging in again the edit saves';
  await a.fill('#login-password', password);
  await a.click('#login-button');
  await a.locator('#session-info').waitFor({ state: 'visible' });
  await a.click('#save-button');
  await a.locator('#frame-notice', { hasText: 'Saved Robot' }).waitFor();
  await a.screenshot({ path: join(artifacts, '11-session-ended.png') });
  console.log('session e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('session e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
