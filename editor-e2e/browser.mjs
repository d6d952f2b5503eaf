// What every editor-e2e script starts with: the editor's address and password and the artifacts directory, as
// org.kicnp.editor.EditorBrowserTest passes them (EDITOR_URL, EDITOR_PASSWORD, ARTIFACTS, CHROMIUM), a check that
// fails the current step, and headless Chromium launched the one way the tests need it.
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
