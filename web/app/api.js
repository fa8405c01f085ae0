// The fosls-serve HTTP API (docs/service.md), as the page uses it. Every call resolves to
// {status, ok, body} (body: parsed JSON, text, or null) and rejects only when the server
// cannot be reached, so callers handle problems (RFC 9457) as data.

async function call(method, path, { body, accept = 'json' } = {}) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.body = body;
    init.headers['Content-Type'] = 'application/json';
  }
  const response = await fetch(path, init);
  let parsed = null;
  const type = response.headers.get('Content-Type') ?? '';
  if (response.status !== 204) {
    const text = await response.text();
    if (accept === 'text' && response.ok) parsed = text;
    else if (type.includes('json')) {
      try {
        parsed = JSON.parse(text);
      } catch {
        parsed = { detail: `unreadable ${type} response` };
      }
    } else parsed = text;
  }
  return { status: response.status, ok: response.ok, body: parsed };
}

/** POST /v1/jobs with the case text exactly as typed (the server parses and validates). */
export const submitCase = (text) => call('POST', '/v1/jobs', { body: text });
/** GET /v1/jobs: the newest jobs first. */
export const listJobs = (pageSize = 50) => call('GET', `/v1/jobs?page_size=${pageSize}`);
/** GET /v1/jobs/{id}. */
export const getJob = (id) => call('GET', `/v1/jobs/${id}`);
/** GET /v1/jobs/{id}/result. */
export const getResult = (id) => call('GET', resultUrl(id));
/** GET /v1/jobs/{id}/solution.vtu as text. */
export const getSolution = (id) => call('GET', solutionUrl(id), { accept: 'text' });
/** GET /v1/jobs/{id}/case: the case as submitted (options.accept 'text' keeps its text). */
export const getCase = (id, options = {}) => call('GET', `/v1/jobs/${id}/case`, options);
/** POST /v1/jobs/{id}/cancel. */
export const cancelJob = (id) => call('POST', `/v1/jobs/${id}/cancel`);
/** DELETE /v1/jobs/{id}. */
export const deleteJob = (id) => call('DELETE', `/v1/jobs/${id}`);

export const resultUrl = (id) => `/v1/jobs/${id}/result`;
export const solutionUrl = (id) => `/v1/jobs/${id}/solution.vtu`;

/** One line for a problem response: its detail, else its title, else the status. */
export function problemMessage(response) {
  const b = response.body;
  if (b && typeof b === 'object') return b.detail || b.title || `HTTP ${response.status}`;
  return `HTTP ${response.status}${typeof b === 'string' && b ? `: ${b.slice(0, 200)}` : ''}`;
}
