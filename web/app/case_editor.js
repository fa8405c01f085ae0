// The case editor: a plain textarea (so typing, undo and screen readers behave as usual) over
// a backdrop that marks the keys the service complained about and writes each message at
// the end of that line, a gutter with line numbers, and a list of pointer → message whose
// entries select the key in the text.
import { locateJson, rangeForPointer, lineOfOffset } from './json_locations.js';

// Beyond this size (a pasted .msh text) the backdrop would copy megabytes on every keystroke;
// the error list still works.
const MAX_ANNOTATED_CHARS = 300_000;

const escapeHtml = (s) =>
  s.replaceAll('&', '&amp;').replaceAll('<', '&lt;').replaceAll('>', '&gt;');

export class CaseEditor {
  /** Elements: textarea, backdrop (pre), gutter (div), errorList (ul), errorBox (section). */
  constructor({ textarea, backdrop, gutter, errorList, errorBox }) {
    this.textarea_ = textarea;
    this.backdrop_ = backdrop;
    this.gutter_ = gutter;
    this.errorList_ = errorList;
    this.errorBox_ = errorBox;
    this.problems_ = [];  // [{pointer, detail}] or [{line, column, detail}] for syntax errors
    this.pending_ = 0;
    textarea.addEventListener('input', () => {
      cancelAnimationFrame(this.pending_);
      this.pending_ = requestAnimationFrame(() => this.render_());
    });
    textarea.addEventListener('scroll', () => this.syncScroll_());
    this.render_();
  }

  get text() {
    return this.textarea_.value;
  }

  set text(value) {
    this.textarea_.value = value;
    this.textarea_.scrollTop = 0;
    this.textarea_.scrollLeft = 0;
    this.render_();
  }

  /** Shows validation errors ([{pointer, detail}]) from a 422 problem. */
  showProblems(errors) {
    this.problems_ = errors.map((e) => ({ pointer: String(e.pointer ?? ''), detail: String(e.detail ?? '') }));
    this.render_();
  }

  /** Shows a JSON syntax error at a 1-based line and column. */
  showSyntaxError(line, column, detail) {
    this.problems_ = [{ line: line - 1, column: column - 1, detail }];
    this.render_();
  }

  clearProblems() {
    this.problems_ = [];
    this.render_();
  }

  /** Selects the text that `problem` is about and scrolls it into view. */
  reveal_(problem) {
    const text = this.text;
    const range = problem.range;
    if (!range) return;
    this.textarea_.focus();
    this.textarea_.setSelectionRange(range.start, range.end);
    // Selection alone does not scroll a textarea in every browser: place the line a third down.
    const lineHeight = parseFloat(getComputedStyle(this.textarea_).lineHeight) || 18;
    const line = lineOfOffset(text, range.start);
    this.textarea_.scrollTop = Math.max(0, (line - 3) * lineHeight);
    this.syncScroll_();
  }

  /** Resolves each problem to a text range and line of the current text. */
  locate_() {
    const text = this.text;
    const { locations } = locateJson(text);
    const lineStarts = [0];
    for (let k = 0; k < text.length; k++) if (text[k] === '\n') lineStarts.push(k + 1);
    return this.problems_.map((p) => {
      if (p.line !== undefined) {
        const line = Math.min(Math.max(p.line, 0), lineStarts.length - 1);
        const start = Math.min(lineStarts[line] + Math.max(p.column, 0), text.length);
        return { ...p, range: { start, end: Math.min(start + 1, text.length), exact: true }, lineIndex: line };
      }
      const range = rangeForPointer(text, locations, p.pointer);
      return { ...p, range, lineIndex: range ? lineOfOffset(text, range.start) : null };
    });
  }

  render_() {
    const text = this.text;
    const located = this.locate_();
    const lines = text.split('\n');

    this.gutter_.innerHTML = '';
    const numbers = document.createDocumentFragment();
    const byLine = new Map();
    for (const p of located) {
      if (p.lineIndex === null) continue;
      if (!byLine.has(p.lineIndex)) byLine.set(p.lineIndex, []);
      byLine.get(p.lineIndex).push(p);
    }
    lines.forEach((_, i) => {
      const div = document.createElement('div');
      div.textContent = String(i + 1);
      if (byLine.has(i)) div.className = 'error-line';
      numbers.append(div);
    });
    this.gutter_.append(numbers);

    if (text.length <= MAX_ANNOTATED_CHARS) {
      // Ghost text is transparent and sits exactly under the textarea's glyphs, so the marks
      // land on the key and the note starts right after the line's last character.
      const marks = located.filter((p) => p.range).map((p) => p.range).sort((a, b) => a.start - b.start);
      let html = '';
      let offset = 0;
      lines.forEach((line, i) => {
        const lineEnd = offset + line.length;
        let body = '';
        let cursor = offset;
        for (const m of marks) {
          if (m.end <= cursor || m.start >= lineEnd || m.start < cursor) continue;
          body += escapeHtml(text.slice(cursor, m.start));
          body += `<mark>${escapeHtml(text.slice(m.start, Math.min(m.end, lineEnd)))}</mark>`;
          cursor = Math.min(m.end, lineEnd);
        }
        body += escapeHtml(text.slice(cursor, lineEnd));
        const notes = byLine.get(i);
        const note = notes
          ? `<span class="note">  ◀ ${escapeHtml(notes.map((p) => p.detail).join('; '))}</span>`
          : '';
        html += `<div class="${notes ? 'error-line' : ''}"><span class="ghost">${body || ' '}</span>${note}</div>`;
        offset = lineEnd + 1;
      });
      this.backdrop_.innerHTML = html;
    } else {
      this.backdrop_.innerHTML = '';
    }

    this.errorList_.innerHTML = '';
    for (const p of located) {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'pointer';
      button.textContent = p.pointer !== undefined ? p.pointer || '(the whole case)' : `line ${p.line + 1}`;
      button.title = 'Select this field in the editor';
      button.disabled = !p.range;
      button.addEventListener('click', () => this.reveal_(p));
      const message = document.createElement('span');
      message.className = 'detail';
      message.textContent = p.detail;
      li.append(button, ' ', message);
      if (p.pointer !== undefined && p.lineIndex !== null) {
        const where = document.createElement('span');
        where.className = 'where';
        where.textContent = p.range.exact ? ` (line ${p.lineIndex + 1})` : ` (missing; its parent is on line ${p.lineIndex + 1})`;
        li.append(where);
      }
      this.errorList_.append(li);
    }
    this.errorBox_.hidden = located.length === 0;
    this.textarea_.setAttribute('aria-invalid', located.length > 0 ? 'true' : 'false');
    this.syncScroll_();
  }

  syncScroll_() {
    this.backdrop_.scrollTop = this.textarea_.scrollTop;
    this.backdrop_.scrollLeft = this.textarea_.scrollLeft;
    this.gutter_.scrollTop = this.textarea_.scrollTop;
  }
}
