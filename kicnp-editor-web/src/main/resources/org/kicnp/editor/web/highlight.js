// A small JavaScript highlighter for the script slots: a transparent textarea sits over a <pre> that shows the
// same text coloured. Hand-written on purpose: no library, nothing from the network. An ES module.
const KEYWORDS = new Set(['var', 'let', 'const', 'if', 'else', 'for', 'while', 'do', 'return', 'function',
  'new', 'true', 'false', 'null', 'undefined', 'this', 'typeof', 'instanceof', 'in', 'of', 'break', 'continue',
  'switch', 'case', 'default', 'throw', 'try', 'catch', 'finally']);
// Strings accept the paper's typographic quotes too (Table 4 prints “…”).
const TOKEN = /(\/\/[^\n]*|\/\*[\s\S]*?(?:\*\/|$))|("(?:[^"\\\n]|\\.)*"?|'(?:[^'\\\n]|\\.)*'?|`(?:[^`\\]|\\.)*`?|“[^”\n]*”?)|(\b\d+(?:\.\d+)?\b)|(\bs\.[A-Za-z_$][\w$]*)|([A-Za-z_$][\w$]*)(?=\s*\()|([A-Za-z_$][\w$]*)/g;

function escape(text) {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

export function highlight(text) {
  let out = '';
  let last = 0;
  TOKEN.lastIndex = 0;
  let m;
  while ((m = TOKEN.exec(text)) !== null) {
    out += escape(text.slice(last, m.index));
    const t = escape(m[0]);
    if (m[1]) out += '<span class="tok-com">' + t + '</span>';
    else if (m[2]) out += '<span class="tok-str">' + t + '</span>';
    else if (m[3]) out += '<span class="tok-num">' + t + '</span>';
    else if (m[4]) out += '<span class="tok-slot">' + t + '</span>';
    else if (m[5]) out += KEYWORDS.has(m[5]) ? '<span class="tok-kw">' + t + '</span>' : '<span class="tok-fn">' + t + '</span>';
    else out += KEYWORDS.has(m[6]) ? '<span class="tok-kw">' + t + '</span>' : t;
    last = m.index + m[0].length;
  }
  // A trailing newline needs a character after it or the <pre> is one line shorter than the textarea.
  return out + escape(text.slice(last)) + '\n';
}

/** Builds an editor: returns {element, textarea}. */
export function editor(id, label, value, onChange) {
  const wrap = document.createElement('div');
  const lab = document.createElement('label');
  lab.htmlFor = id;
  lab.textContent = label;
  const code = document.createElement('div');
  code.className = 'code';
  const pre = document.createElement('pre');
  pre.setAttribute('aria-hidden', 'true');
  const area = document.createElement('textarea');
  area.id = id;
  area.spellcheck = false;
  area.rows = 4;
  area.value = value || '';
  const sync = () => {
    pre.innerHTML = highlight(area.value);
    pre.scrollTop = area.scrollTop;
  };
  area.addEventListener('input', () => { sync(); onChange(area.value); });
  area.addEventListener('scroll', () => { pre.scrollTop = area.scrollTop; });
  area.addEventListener('keydown', (e) => {
    if (e.key === 'Tab' && !e.shiftKey && e.ctrlKey) { // Ctrl+Tab inserts a tab; plain Tab keeps moving focus.
      e.preventDefault();
      area.setRangeText('  ', area.selectionStart, area.selectionEnd, 'end');
      sync();
      onChange(area.value);
    }
  });
  code.append(pre, area);
  wrap.append(lab, code);
  sync();
  return { element: wrap, textarea: area };
}

