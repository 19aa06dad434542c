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

// `text` with the entries of a segment's source (`{ span, tables }` of the API) replaced; entries
// written as `[[segment.ssvs]]` tables become an `ssvs = [...]` key in their place.
export function splice(text, { span, tables }, entries) {
  const array = tables ? `ssvs = ${arrayText(entries)}\n` : arrayText(entries);
  return text.slice(0, span[0]) + array + text.slice(span[1]);
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

// A `[[pair]]` table of segments a and b.
export function pairTable(a, b) {
  return `[[pair]]\na = ${JSON.stringify(a)}\nb = ${JSON.stringify(b)}\n`;
}

// `text` with a new `[[pair]]` table after the last of `tables` (or at the end of the file).
export function addPairTable(text, tables, a, b) {
  const at = tables.length > 0 ? tables[tables.length - 1].span[1] : text.length;
  const before = text.slice(0, at);
  const gap = before === '' || before.endsWith('\n\n') ? '' : before.endsWith('\n') ? '\n' : '\n\n';
  return before + gap + pairTable(a, b) + text.slice(at);
}

// `text` without the `[start, end)` span.
export const cut = (text, [start, end]) => text.slice(0, start) + text.slice(end);

// An explicit `ssvs` entry of an SSV as the API expands it (kind, points, radius).
export function entryOf(ssv) {
  const geometry = ssv.kind === 'point' ? ssv.points[0] : ssv.points;
  return { [ssv.kind]: geometry, radius: ssv.radius };
}

// `text` with a mirrored segment made explicit: its `mirror_of` line becomes the `ssvs` array
// of its current SSVs and its `plane` line goes (`lines`: the spans of the two lines).
export function detached(text, lines, ssvs) {
  const [first, second] = [...lines].sort((p, q) => p[0] - q[0]);
  const array = `ssvs = ${arrayText(ssvs.map(entryOf))}\n`;
  const replaced = (span) => (span === lines[0] ? array : '');
  return text.slice(0, first[0]) + replaced(first) + text.slice(first[1], second[0]) + replaced(second)
    + text.slice(second[1]);
}
