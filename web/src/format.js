// The TOML text of a segment's `ssvs` entries, spliced into the file text at the array's
// span so that the rest of the file (comments, other segments, pairs) stays as written.

// A TOML float: integers get a decimal point, non-finite values the TOML words (which the
// server's loader then rejects with a located message).
export function number(x) {
  if (Number.isNaN(x)) return 'nan';
  if (!Number.isFinite(x)) return x > 0 ? 'inf' : '-inf';
  return Number.isInteger(x) ? x.toFixed(1) : String(x);
}

const vec = (v) => `[${v.map(number).join(', ')}]`;

export function kindOf(entry) {
  return ['point', 'line', 'triangle'].find((k) => entry[k] !== undefined && entry[k] !== null);
}

// The entry's vertices as a list of [x, y, z].
export function vertices(entry) {
  const k = kindOf(entry);
  return k === 'point' ? [entry.point] : entry[k];
}

export function entryText(entry) {
  const k = kindOf(entry);
  const geometry = k === 'point' ? vec(entry.point) : `[${entry[k].map(vec).join(', ')}]`;
  const copy = entry.mirror_copy ? `, mirror_copy = "${entry.mirror_copy}"` : '';
  return `{ ${k} = ${geometry}, radius = ${number(entry.radius)}${copy} }`;
}

export function arrayText(entries) {
  return `[\n${entries.map((e) => `  ${entryText(e)},\n`).join('')}]`;
}

export function splice(text, span, entries) {
  return text.slice(0, span[0]) + arrayText(entries) + text.slice(span[1]);
}

// The entry mirrored about a body axis plane (`xy`, `yz`, `xz`).
export function mirrored(entry, plane) {
  const axis = { yz: 0, xz: 1, xy: 2 }[plane];
  const flip = (v) => v.map((x, i) => (i === axis ? -x : x));
  const k = kindOf(entry);
  const out = structuredClone(entry);
  out[k] = k === 'point' ? flip(entry.point) : entry[k].map(flip);
  return out;
}

// The text of the `pairs = [...]` array.
export function pairsText(pairs) {
  return `[\n${pairs.map(([a, b]) => `  ["${a}", "${b}"],\n`).join('')}]`;
}
