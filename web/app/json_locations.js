// Where each JSON pointer (RFC 6901) of a JSON text sits in that text, so that an error
// the service reports for "/material/mu" can be shown on the line that holds "mu".
// The browser's JSON.parse gives values but no positions, hence this small scanner. It
// accepts exactly JSON; on a syntax error it keeps what it located before the error.

/** Escapes one reference token: "~" → "~0", "/" → "~1". */
export function escapePointerToken(token) {
  return String(token).replaceAll('~', '~0').replaceAll('/', '~1');
}

/** Splits a pointer into unescaped tokens ("" → [], "/a~1b/0" → ["a/b", "0"]). */
export function splitPointer(pointer) {
  if (pointer === '' || pointer === undefined || pointer === null) return [];
  if (!pointer.startsWith('/')) return [pointer];  // lenient: a bare name
  return pointer
    .slice(1)
    .split('/')
    .map((t) => t.replaceAll('~1', '/').replaceAll('~0', '~'));
}

/**
 * Scans `text` and returns {locations, error}: locations maps every pointer found to
 * {start, end, keyStart, keyEnd} (character offsets; keyStart/keyEnd only for object
 * members, end exclusive), error is null or {offset, message}.
 */
export function locateJson(text) {
  const locations = new Map();
  let i = 0;

  const fail = (message) => {
    const e = new Error(message);
    e.offset = i;
    throw e;
  };
  const skipSpace = () => {
    while (i < text.length && ' \t\n\r'.includes(text[i])) i++;
  };
  const scanString = () => {
    if (text[i] !== '"') fail('expected a string');
    let out = '';
    i++;
    while (i < text.length) {
      const c = text[i];
      if (c === '"') {
        i++;
        return out;
      }
      if (c === '\\') {
        const n = text[i + 1];
        const simple = { '"': '"', '\\': '\\', '/': '/', b: '\b', f: '\f', n: '\n', r: '\r', t: '\t' };
        if (n in simple) {
          out += simple[n];
          i += 2;
        } else if (n === 'u' && /^[0-9a-fA-F]{4}$/.test(text.slice(i + 2, i + 6))) {
          out += String.fromCharCode(parseInt(text.slice(i + 2, i + 6), 16));
          i += 6;
        } else {
          fail('invalid escape in a string');
        }
      } else if (c < ' ') {
        fail('control character in a string');
      } else {
        out += c;
        i++;
      }
    }
    fail('unterminated string');
  };
  const scanLiteral = () => {
    const m = /^(-?(0|[1-9]\d*)(\.\d+)?([eE][+-]?\d+)?|true|false|null)/.exec(text.slice(i, i + 400));
    if (!m) fail('expected a value');
    i += m[0].length;
  };
  const scanValue = (pointer, key) => {
    skipSpace();
    const start = i;
    if (text[i] === '{') {
      i++;
      skipSpace();
      if (text[i] === '}') {
        i++;
      } else {
        for (;;) {
          skipSpace();
          const keyStart = i;
          const name = scanString();
          const keyEnd = i;
          skipSpace();
          if (text[i] !== ':') fail('expected ":" after a key');
          i++;
          scanValue(`${pointer}/${escapePointerToken(name)}`, { keyStart, keyEnd });
          skipSpace();
          if (text[i] === ',') {
            i++;
            continue;
          }
          if (text[i] === '}') {
            i++;
            break;
          }
          fail('expected "," or "}"');
        }
      }
    } else if (text[i] === '[') {
      i++;
      skipSpace();
      if (text[i] === ']') {
        i++;
      } else {
        for (let index = 0; ; index++) {
          scanValue(`${pointer}/${index}`, null);
          skipSpace();
          if (text[i] === ',') {
            i++;
            continue;
          }
          if (text[i] === ']') {
            i++;
            break;
          }
          fail('expected "," or "]"');
        }
      }
    } else if (text[i] === '"') {
      scanString();
    } else {
      scanLiteral();
    }
    locations.set(pointer, { start, end: i, ...(key ?? {}) });
  };

  try {
    scanValue('', null);
    skipSpace();
    if (i < text.length) fail('unexpected text after the JSON value');
    return { locations, error: null };
  } catch (e) {
    return { locations, error: { offset: e.offset ?? i, message: e.message } };
  }
}

/**
 * The text range of `text` to mark for `pointer`: the member's key (or the element's
 * value) when it exists, else the nearest existing ancestor (a missing field is reported
 * on its parent). Returns {start, end, exact} or null when nothing was located.
 */
export function rangeForPointer(text, locations, pointer) {
  const tokens = splitPointer(pointer);
  for (let n = tokens.length; n >= 0; n--) {
    const p = tokens.slice(0, n).map((t) => '/' + escapePointerToken(t)).join('');
    const loc = locations.get(p);
    if (!loc) continue;
    const exact = n === tokens.length;
    if (loc.keyStart !== undefined) return { start: loc.keyStart, end: loc.keyEnd, exact };
    // An array element or the root: its first line only, not a whole block.
    const newline = text.indexOf('\n', loc.start);
    return { start: loc.start, end: newline < 0 ? loc.end : Math.min(loc.end, newline), exact };
  }
  return null;
}

/** 0-based line of a character offset. */
export function lineOfOffset(text, offset) {
  let line = 0;
  for (let k = 0; k < offset && k < text.length; k++) if (text[k] === '\n') line++;
  return line;
}
