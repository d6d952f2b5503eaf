// End-to-end test of the knowledge editor in a real headless Chromium, driven by Playwright.
// Started by org.kicnp.editor.EditorBrowserTest, which runs the editor server and passes:
//   EDITOR_URL (http://127.0.0.1:PORT/), EDITOR_PASSWORD, ARTIFACTS (a directory for screenshots),
//   CHROMIUM (the browser executable, /usr/bin/chromium by default).
// Exits 0 when every step passed; otherwise prints the failed step and exits 1.
import { join } from 'node:path';
import { artifacts, base, check, launch, password } from './browser.mjs';

const problems = [];
const expectedNetworkErrors = /Failed to load resource: the server responded with a status of (401|409|422)/;
let step = 'launch';

const browser = await launch();
let failed = false;
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  page.setDefaultTimeout(10000);
  page.on('console', (m) => {
    if (m.type() === 'error' && !expectedNetworkErrors.test(m.text())) problems.push('console: ' + m.text());
  });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  page.on('request', (r) => {
    if (!r.url().startsWith(base.replace(/\/$/, '')) && !r.url().startsWith(base.replace('http', 'ws').replace(/\/$/, ''))) {
      problems.push('request outside the editor: ' + r.url());
    }
  });

  step = 'open the hierarchy';
  await page.goto(base);
  const tree = page.locator('#tree');
  await tree.locator('[data-frame="AskUserName"]').waitFor();
  check(await tree.locator('.frame-button.instance[data-frame="Robovie"]').count() === 1, 'Robovie is not shown as an instance');
  check(await tree.locator('[data-frame="Taro"] .learned-mark').count() === 1, 'the learned frame Taro is not marked');
  check(await tree.locator('[data-frame="Greeting"] .link-mark').count() === 1, 'Greeting\'s semantic link is not shown');
  await page.locator('#live:not(.off)').waitFor();
  await page.screenshot({ path: join(artifacts, '01-hierarchy.png') });

  step = 'search the hierarchy';
  await page.fill('#search', 'user');
  check(await tree.locator('.frame-button.match').count() === 4, 'search for "user" did not mark 4 frames');
  check(await tree.locator('[data-frame="Robovie"]').count() === 0, 'search did not hide Robovie');
  await page.fill('#search', '');

  step = 'read-only before login: a frame opens but cannot be edited';
  await tree.locator('[data-frame="Greeting"]').click();
  await page.locator('#frame-title', { hasText: 'Greeting' }).waitFor();
  check(await page.isDisabled('#save-button'), 'Save is enabled without a login');
  check(await page.isDisabled('input[aria-label="mUser argument"]'), 'slot inputs are editable without a login');
  check(await page.isVisible('#readonly-note'), 'the read-only note is not shown');
  await page.screenshot({ path: join(artifacts, '00-read-only.png') });

  step = 'log in with a wrong password';
  await page.fill('#login-password', 'not the password');
  await page.press('#login-password', 'Enter');
  await page.locator('#login-error').waitFor({ state: 'visible' });
  check((await page.textContent('#login-error')).includes('Wrong password'), 'wrong password not refused in words');
  check(await page.isVisible('#login-form'), 'login form vanished after a wrong password');

  step = 'log in';
  await page.fill('#login-password', password);
  await page.click('#login-button');
  await page.locator('#session-info').waitFor({ state: 'visible' });

  step = 'open a frame with the keyboard';
  await tree.locator('[data-frame="AskUserName"]').focus();
  await page.keyboard.press('Enter');
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();
  const inherited = page.locator('tr.inherited[data-slot-name="mfunction"]');
  await inherited.waitFor();
  check((await inherited.textContent()).includes('from Speech'), 'inherited slot does not name Speech');
  check(await page.locator('#slot-table thead th').count() === 14, 'the slot table does not show every Table 2 facet');

  step = 'edit a slot into a validation error';
  await page.fill('input[aria-label="mUser argument"]', 'Martian');
  await page.fill('input[aria-label="mUser role"]', 'the visitor asked for a name');
  await page.click('#save-button');
  await page.locator('#frame-errors').waitFor({ state: 'visible' });
  const errorText = await page.textContent('#frame-errors');
  check(errorText.includes("'Martian'"), 'the validation error does not name the unknown class: ' + errorText);
  check(await page.locator('tr.own.invalid[data-slot-name="mUser"]').count() === 1, 'the faulty slot row is not marked');
  await page.screenshot({ path: join(artifacts, '02-validation-error.png'), fullPage: true });

  step = 'fix and save';
  await page.fill('input[aria-label="mUser argument"]', 'KnownUser');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved AskUserName' }).waitFor();
  check(await page.isHidden('#frame-errors'), 'the error box stayed after a good save');

  step = 'edit a script slot: a syntax error is caught before saving';
  await page.click('button[aria-label="Edit script onInstantiate"]');
  const script = page.locator('textarea[id$="-value"]');
  await script.waitFor();
  check(await page.locator('.code pre .tok-fn').count() > 0, 'the script is not highlighted');
  const revision = await page.textContent('#frame-meta');
  await script.fill('sendmsg(s.mMouth, "What is your name?";');
  await page.click('#save-button');
  await page.locator('#frame-errors', { hasText: 'syntax error' }).waitFor();
  check(await page.textContent('#frame-meta') === revision, 'a script with a syntax error was saved');
  await script.fill('sendmsg(s.mMouth, “What is your name?”);');
  await page.click('#save-button');
  await page.locator('#frame-notice', { hasText: 'Saved AskUserName' }).waitFor();

  step = 'live update: a frame another user creates appears without a reload';
  const other = await browser.newContext();
  const login = await other.request.post(base + 'api/login', { data: { password } });
  check(login.ok(), 'the second user could not log in');
  const created = await other.request.post(base + 'api/frames',
    { data: { name: 'PINO', kind: 'INSTANCE', parent: 'HumanoidRobot' } });
  check(created.status() === 201, 'the second user could not create PINO: ' + created.status());
  await tree.locator('[data-frame="PINO"]').waitFor();
  await other.close();

  step = 'create a sub-frame and delete it';
  await tree.locator('[data-frame="Robot"]').click();
  await page.locator('#frame-title', { hasText: 'Robot' }).waitFor();
  await page.click('#new-child-button');
  await page.fill('#create-name', 'Scout');
  check(await page.inputValue('#create-parent') === 'Robot', 'a new sub-frame does not default to its parent');
  await page.press('#create-name', 'Enter');
  await page.locator('#frame-title', { hasText: 'Scout' }).waitFor();
  await tree.locator('[data-frame="Scout"]').waitFor();
  await page.click('#delete-button');
  await page.click('#delete-apply');
  await page.locator('#welcome').waitFor({ state: 'visible' });
  await tree.locator('[data-frame="Scout"]').waitFor({ state: 'detached' });
  await tree.locator('[data-frame="AskUserName"]').click();
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();

  step = 'import XML: an error is shown with its line, a good file is imported';
  await page.click('#import-button');
  await page.fill('#import-text', '<KNOWLEDGEBASE>\n  <FRAME><NAME>AIBO</NAME><ISA>RobotDog</ISA></FRAME>\n</KNOWLEDGEBASE>');
  await page.click('#import-apply');
  await page.locator('#import-errors', { hasText: 'line 2' }).waitFor();
  await page.fill('#import-text', '<KNOWLEDGEBASE>\n  <FRAME><NAME>AIBO</NAME><ISA>Robot</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>\n</KNOWLEDGEBASE>');
  await page.click('#import-apply');
  await page.locator('#welcome-text', { hasText: 'Imported 1 frame' }).waitFor();
  await tree.locator('[data-frame="AIBO"]').waitFor();

  step = 'export XML as a download';
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-button')]);
  check(download.suggestedFilename() === 'knowledge.xml', 'the export is not named knowledge.xml');
  await tree.locator('[data-frame="AskUserName"]').click();
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();

  step = 'a frame someone else saved meanwhile is never overwritten';
  await tree.locator('[data-frame="Greeting"]').click();
  await page.locator('#frame-title', { hasText: 'Greeting' }).waitFor();
  await page.fill('input[aria-label="mUser role"]', 'my edit');
  const rival = await browser.newContext();
  await rival.request.post(base + 'api/login', { data: { password } });
  const theirs = await (await rival.request.get(base + 'api/frames/Greeting')).json();
  theirs.expectedRevision = theirs.revision;
  theirs.slots[0].role = 'their edit';
  const put = await rival.request.put(base + 'api/frames/Greeting', { data: theirs });
  check(put.status() === 200, 'the rival could not save Greeting: ' + put.status());
  await rival.close();
  await page.locator('#stale-note', { hasText: 'Someone else changed Greeting' }).waitFor();
  await page.click('#save-button');
  await page.locator('#frame-errors', { hasText: 'was changed by someone else' }).waitFor();
  await page.click('#stale-note button');
  await page.waitForFunction(() => document.querySelector('input[aria-label="mUser role"]').value === 'their edit');
  await tree.locator('[data-frame="AskUserName"]').click();
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();

  step = 'reload and find the change';
  await page.reload();
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();
  check(await page.inputValue('input[aria-label="mUser argument"]') === 'KnownUser', 'the argument did not survive a reload');
  check(await page.inputValue('input[aria-label="mUser role"]') === 'the visitor asked for a name', 'the role did not survive a reload');
  await page.click('button[aria-label="Edit script onInstantiate"]');
  await page.locator('.code pre').first().waitFor();
  await page.screenshot({ path: join(artifacts, '03-slot-table.png') });
  await page.screenshot({ path: join(artifacts, '03-slot-table-full.png'), fullPage: true });

  step = 'inference view: run, see the derived instance, ask why and why not, read the trace';
  await page.click('#inference-button');
  await page.locator('#inference-panel').waitFor({ state: 'visible' });
  await page.click('#run-button');
  const derivedRow = page.locator('#wm-rows tr', { hasText: 'derived' }).filter({ hasText: 'AskUserName' });
  await derivedRow.waitFor();
  await derivedRow.locator('button', { hasText: 'Why?' }).click();
  await page.locator('#why-tree', { hasText: 'made by AskUserName' }).waitFor();
  check((await page.textContent('#why-tree')).includes('visitor1'), 'why does not rest on visitor1');
  await page.locator('#trace-log li.Fired').first().waitFor();
  await page.fill('#ask-class', 'AskUserName');
  await page.click('#prove-button');
  await page.locator('#ask-answers li', { hasText: 'AskUserName' }).first().waitFor();
  await page.screenshot({ path: join(artifacts, '04-inference.png') });
  await page.click('#why-not-button');
  await page.locator('#ask-answers li.why-not-summary', { hasText: "'AskUserName' has 1 binding: 1 blocked." }).waitFor();
  check((await page.textContent('#ask-answers')).includes('refraction: this binding has already fired'),
    'why not does not say the binding fired already');
  await page.screenshot({ path: join(artifacts, '04b-why-not.png') });
  await tree.locator('[data-frame="AskUserName"]').first().click();
  await page.locator('#frame-title', { hasText: 'AskUserName' }).waitFor();
  await page.click('#why-not-frame-button');
  await page.locator('#inference-panel').waitFor({ state: 'visible' });
  await page.locator('#ask-answers li.why-not-summary', { hasText: "'AskUserName' has 1 binding: 1 blocked." }).waitFor();
  await tree.locator('[data-frame="Mouth"]').first().click();
  await page.locator('#frame-title', { hasText: 'Mouth' }).waitFor();
  check(await page.isHidden('#why-not-frame-button'), 'Why not? is offered on a class that is no behavior frame');

  step = 'delete an instance: what was derived from it goes too';
  await tree.locator('[data-frame="mouth1"]').click();
  await page.locator('#frame-title', { hasText: 'mouth1' }).waitFor();
  await page.click('#delete-button');
  check((await page.textContent('#delete-question')).includes('The instances derived from it go with it.'),
    'deleting an instance does not say that what was derived from it goes too');
  await page.click('#delete-apply');
  await page.locator('#welcome-text', { hasText: 'Deleted mouth1, and with it what rested on it: AskUserName' })
    .waitFor();
  await tree.locator('[data-frame="mouth1"]').waitFor({ state: 'detached' });

  step = 'world panel: the room is drawn and the robots listed';
  await page.click('#world-button');
  await page.locator('#world-panel').waitFor({ state: 'visible' });
  for (const name of ['robovie', 'scout', 'aibo']) await page.locator('#robot-rows tr[data-robot="' + name + '"]').waitFor();
  check((await page.textContent('#robot-rows tr[data-robot="scout"]')).includes('go_to'), 'scout\'s current action is not shown');
  await page.locator('#world-time', { hasText: 't = ' }).waitFor();
  const paint = await page.evaluate(() => {
    const c = document.getElementById('world-canvas');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    let painted = 0;
    for (let i = 0; i < data.length; i += 16) {
      if (data[i + 3] > 0) painted++;
      colours.add((data[i] >> 4) + ',' + (data[i + 1] >> 4) + ',' + (data[i + 2] >> 4));
    }
    return { painted, colours: colours.size, width: c.width };
  });
  check(paint.width > 300 && paint.painted > 1000 && paint.colours > 8, 'the room canvas looks blank: ' + JSON.stringify(paint));
  const firstTime = await page.textContent('#world-time');
  await page.waitForFunction((t) => document.getElementById('world-time').textContent !== t, firstTime);

  step = 'world panel: speak as User A and read the verdict and the reply';
  await page.fill('#chat-text', 'Bring me a cup of tea');
  await page.press('#chat-text', 'Enter');
  await page.locator('#chat-log li.chat-user', { hasText: 'Bring me a cup of tea' }).waitFor();
  await page.locator('#chat-log li.chat-understood', { hasText: 'bring tea' }).waitFor();
  await page.locator('#chat-log li.chat-robot', { hasText: 'Scout will bring you tea.' }).waitFor();
  check(await page.inputValue('#chat-text') === '', 'the chat box was not cleared after speaking');

  step = 'world panel: tele-operate scout and see the feedback';
  await page.selectOption('#teleop-robot', 'scout');
  await page.selectOption('#teleop-action', 'go_to');
  await page.fill('#arg-x', '7.0');
  await page.fill('#arg-y', '3.5');
  await page.click('#teleop-send');
  const command = page.locator('#command-rows tr', { hasText: 'go_to' });
  await command.locator('.status-ended').waitFor();
  check((await command.textContent()).includes('done'), 'the command\'s result is not shown');

  step = 'world panel: mark the command wrong';
  await command.locator('button', { hasText: 'Wrong' }).click();
  await page.locator('#wrong-form').waitFor({ state: 'visible' });
  await page.fill('#wrong-reason', 'went to the wrong place');
  await page.press('#wrong-reason', 'Enter');
  await command.locator('.wrong-note', { hasText: 'went to the wrong place' }).waitFor();
  await page.locator('#wrong-form').waitFor({ state: 'hidden' });
  check(await command.locator('button', { hasText: 'Stop' }).count() === 0, 'a command that ended offers Stop');

  step = 'world panel: stop a command under way';
  await page.selectOption('#teleop-action', 'patrol');
  await page.click('#teleop-send');
  const patrol = page.locator('#command-rows tr', { hasText: 'patrol' });
  await patrol.locator('.status-started').waitFor();
  await patrol.locator('button', { hasText: 'Stop' }).click();
  await patrol.locator('.status-failed').waitFor();
  check((await patrol.textContent()).includes('cancelled: stopped in the editor'), 'the stop\'s reason is not shown');
  check((await patrol.textContent()).includes('stop asked: stopped in the editor'), 'the stop request is not noted');
  check(await patrol.locator('button', { hasText: 'Stop' }).count() === 0, 'a stopped command still offers Stop');
  check(await page.locator('#robot-rows button[aria-label="Stop action c9 (go_to of scout)"]').count() === 1,
    'the robot list does not offer Stop on scout\'s running action');

  step = 'world panel: the robot list keeps keyboard focus while the robots move';
  const rowWrong = page.locator('#robot-rows tr[data-robot="scout"] button', { hasText: 'Wrong' });
  await rowWrong.focus();
  await page.waitForTimeout(400);
  check(await rowWrong.evaluate((b) => document.activeElement === b), 'the robot list lost keyboard focus while the robots moved');
  await page.keyboard.press('Enter');
  await page.locator('#wrong-form').waitFor({ state: 'visible' });
  check((await page.textContent('#wrong-question')).includes('c9'), 'the wrong form does not name the running action c9');
  await page.click('#wrong-cancel');
  await page.locator('#chat-text').focus();
  await page.screenshot({ path: join(artifacts, '05-world.png') });

  step = 'no console errors';
  check(problems.length === 0, problems.join('\n'));
  console.log('editor e2e: all steps passed');
} catch (e) {
  failed = true;
  console.error('editor e2e failed at step "' + step + '": ' + e.message);
  if (problems.length) console.error(problems.join('\n'));
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
