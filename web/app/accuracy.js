// A run to a requested force accuracy (the result's `accuracy`, docs/result-format.md) in one
// key number: whether it was reached, the estimate against the request, and the levels. Pure,
// so node's test runner checks it.
import { fmt } from './format.js';

const percent = (v) => (Number.isFinite(v) ? `${fmt(100 * v, 2)} %` : '—');

/** [value, title] of the key number "Force accuracy", or null without an accuracy section. */
export function accuracyNumber(accuracy) {
  if (!accuracy) return null;
  const levels = accuracy.steps?.length ?? 0;
  const first = accuracy.steps?.[0]?.refinements;
  const last = accuracy.steps?.[levels - 1]?.refinements;
  const range = levels > 1 ? `refinements ${first}–${last}` : `refinements ${first ?? '—'}`;
  const estimate = `estimated ${percent(accuracy.estimate)} of ${percent(accuracy.force)} asked`;
  const value = accuracy.reached
    ? `reached: ${estimate} (${range})`
    : `NOT reached (${accuracy.stop_reason}): ${estimate} (${range})`;
  return [value, accuracy.stop_message ?? ''];
}
