// End-to-end check that only the paper's procedural slots are edited and checked as scripts, in headless Chromium:
// Cup has a string slot onTable ("kitchen counter"), which is data, not a script (the platform runs only onInstantiate
// and onDestroy). The table must show it as a plain value and save a new one without a syntax check refusing it, while
// Cup's onInstantiate stays a script. Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL,
// EDITOR_PASSWORD, ARTIFACTS and CHROMIUM as editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the
// failed step and exits 1.
import { join } from 'node:path';
import { artifacts, check, launch, logIn, newPage, openFrame } from './browser.mjs';

let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const page = await newPage(browser);

  step = 'log in and open Cup';
  await logIn(page);
  await openFrame(page, 'Cup');

  step = 'onTable is a plain value, onInstantiate a script';
  const onTable = page.locator('input[aria-label="onTable value"]');
  check(await onTable.count() === 1, 'onTable is not edited as a plain value');
  check(await onTable.inputValue() === 'kitchen counter', 'onTable does not show its value');
  check(await page.locator('button[aria-label="Edit script onInstantiate"]').count() === 1,
    'onInstantiate is not edited as a script');

  step = 'a new value of onTable saves';
  await onTable.fill('by the sink, left');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved Cup' }).waitFor();
  check(await page.isHidden('#frame-errors'), 'the save showed errors: ' + await page.textContent('#frame-errors'));
  await page.screenshot({ path: join(artifacts, '16-plain-on-slot.png') });
  console.log('plain-on-slot e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('plain-on-slot e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
