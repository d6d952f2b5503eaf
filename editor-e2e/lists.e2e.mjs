// End-to-end check of editing a list value whose items hold commas, in headless Chromium: Phrases.lines is
// ["Hello, Ken", "Bye"]; the table must show it so that adding an item and saving keeps the items as they were.
// Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as
// editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, launch, password } from './browser.mjs';

let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);

  step = 'log in and open Phrases';
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
  await page.locator('#tree [data-frame="Phrases"]').click();
  await page.locator('#frame-title', { hasText: 'Phrases' }).waitFor();

  step = 'add an item to the list and save';
  const lines = page.locator('input[aria-label="lines value"]');
  await lines.fill(await lines.inputValue() + ', See you');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved Phrases' }).waitFor();
  await page.screenshot({ path: join(artifacts, '12-list-items.png') });
  console.log('lists e2e: saved ' + await lines.inputValue());
} catch (e) {
  failed = true;
  console.error('lists e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
