// What every editor-e2e script starts with: the editor's address and password and the artifacts directory, as
// org.kicnp.editor.EditorBrowserTest passes them (EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS, CHROMIUM), a check that
// fails the current step, headless Chromium launched the one way the tests need it, and the steps most scripts
// begin with: a page, logging in, opening a frame.
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';

export const base = process.env.EDITOR_URL;
export const password = process.env.EDITOR_PASSWORD;
export const artifacts = process.env.ARTIFACTS || 'target/e2e';
mkdirSync(artifacts, { recursive: true });

/** Fails the current step with `message` unless `condition` holds. */
export function check(condition, message) {
  if (!condition) throw new Error(message);
}

/** Headless Chromium (the CHROMIUM binary, else /usr/bin/chromium) without sandbox, GPU or background traffic. */
export function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
}

/** A page of 1280×800 in a new browser context, waiting 10 s at most for each step. */
export async function newPage(browser) {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  page.setDefaultTimeout(10000);
  return page;
}

/** Opens the editor on `page`, waits for its live connection and logs in with the editor's password. */
export async function logIn(page) {
  await page.goto(base);
  await page.locator('#live:not(.off)').waitFor();
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });
}

/** Opens frame `name` from the frame tree and waits for its page. */
export async function openFrame(page, name) {
  await page.locator(`#tree [data-frame="${name}"]`).click();
  await page.locator('#frame-title', { hasText: name }).waitFor();
}
