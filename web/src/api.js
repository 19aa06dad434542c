// The server's JSON API (documented in the biped_view crate).

async function answer(response) {
  const text = await response.text();
  let body;
  try { body = JSON.parse(text); } catch { body = { error: text }; }
  if (!response.ok) throw new Error(body.error || `${response.status} ${response.statusText}`);
  return body;
}

export const getJson = (url) => fetch(url).then(answer);
export const getText = (url) => fetch(url).then((r) => r.text());
export const putSsv = (text) => fetch('/api/ssv', { method: 'PUT', body: text }).then(answer);
// `at` is the query naming the shown frame (`?frame=K&recording=NAME`), or ''.
export const checkSsv = (text, at) =>
  fetch(`/api/ssv/check${at}`, { method: 'POST', body: text }).then(answer);

// Every frame of a recording, following the pages.
export async function getRecording(name) {
  let url = `/api/recording?name=${encodeURIComponent(name)}`;
  const first = await getJson(url);
  const all = { ...first, poses: first.poses.slice(), com: first.com && first.com.slice(),
    zmp: first.zmp && first.zmp.slice(), forces: first.forces.map((f) => ({ ...f })) };
  let next = first.next;
  while (next !== null && next !== undefined) {
    const page = await getJson(`${url}&from=${next}`);
    all.poses.push(...page.poses);
    if (all.com) all.com.push(...page.com);
    if (all.zmp) all.zmp.push(...page.zmp);
    page.forces.forEach((f, i) => {
      all.forces[i].origin.push(...f.origin);
      all.forces[i].force.push(...f.force);
    });
    next = page.next;
  }
  return all;
}

// One column of a recording over all frames.
export async function getSignal(name, column) {
  const values = [];
  let from = 0;
  for (;;) {
    const q = `name=${encodeURIComponent(name)}&from=${from}&signals=${encodeURIComponent(column)}`;
    const page = await getJson(`/api/recording?${q}`);
    values.push(...page.signals[column]);
    if (page.next === null || page.next === undefined) return values;
    from = page.next;
  }
}
