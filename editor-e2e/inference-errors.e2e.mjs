// End-to-end check of the inference view's error messages, in headless Chromium: an error belongs to the question
// that caused it, so it goes when the next question is answered, and a refused question does not leave the last
// question's answers standing under it. Started by org.kicnp.editor.EditorBrowserTest with EDITOR_URL, ARTIFACTS
// and CHROMIUM as editor.e2e.mjs. Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch, newPage } from './browser.mjs';

let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const page = await newPage(browser);
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.click('#inference-button');
  await page.locator('#inference-panel').waitFor({ state: 'visible' });

  step = 'asking about an unknown class is refused in words';
  await page.fill('#ask-class', 'Nope');
  await page.press('#ask-class', 'Enter');
  await page.locator('#inference-errors').waitFor({ state: 'visible' });
  check((await page.textContent('#inference-errors')).includes('Nope'), 'the error does not name the class');

  step = 'a reload of the view (as opening it, a refresh or a live event starts) leaves the question\'s error';
  await Promise.all([
    page.waitForResponse((r) => new URL(r.url()).pathname === '/api/inference'),
    page.click('#inference-refresh'),
  ]);
  await page.evaluate(() => new Promise((done) => setTimeout(done, 200))); // the page has applied the answer
  check(await page.isVisible('#inference-errors'), 'the reload of the view hid the error about Nope');
  check((await page.textContent('#inference-errors')).includes('Nope'), 'the error no longer names the class');

  step = 'the next question answered clears that error';
  await page.fill('#ask-class', 'Robot');
  await page.press('#ask-class', 'Enter');
  await page.locator('#ask-answers li', { hasText: 'Robovie' }).waitFor();
  check(await page.isHidden('#inference-errors'),
    'the error about Nope is still shown over the answers about Robot: ' + await page.textContent('#inference-errors'));

  step = 'a refused why-not does not leave the answers about Robot standing under its error';
  await page.click('#why-not-button');
  await page.locator('#inference-errors').waitFor({ state: 'visible' });
  check((await page.textContent('#inference-errors')).includes('Robot'), 'the why-not error does not name Robot');
  check(await page.locator('#ask-answers li').count() === 0,
    'the earlier answers are still listed under the why-not error: ' + await page.textContent('#ask-answers'));
  await page.screenshot({ path: join(artifacts, '09-inference-errors.png') });
  console.log('inference errors e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('inference errors e2e failed at step "' + step + '": ' + e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
