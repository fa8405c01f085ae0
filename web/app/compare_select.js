// The "compare with" choice of the job view: any other job with a result, whose pressure and
// gap (and sweep curve) are then drawn dashed over the shown job's.

/** Jobs that have a result: succeeded, or failed for not converging (the result is kept). */
const hasResult = (job) => job.state === 'succeeded' || ((job.state === 'failed' || job.state === 'cancelled') && job.converged === false);

export class CompareSelect {
  /** select: the <select>; onChange(job or null): called when the user picks another. */
  constructor(select, onChange) {
    this.select_ = select;
    this.jobs_ = new Map();
    select.addEventListener('change', () => onChange(this.jobs_.get(select.value) ?? null));
  }

  /** Lists the jobs with a result other than `shownId`; keeps the choice while it is listed. */
  update(jobs, shownId) {
    const keep = this.select_.value;
    this.jobs_ = new Map(jobs.filter((j) => hasResult(j) && j.id !== shownId).map((j) => [String(j.id), j]));
    const options = [new Option('none', '')];
    for (const [id, job] of this.jobs_) options.push(new Option(`job ${id} · ${job.name}`, id));
    this.select_.replaceChildren(...options);
    this.select_.value = this.jobs_.has(keep) ? keep : '';
    return this.select_.value !== keep;  // the choice was dropped
  }

  clear() {
    this.select_.value = '';
  }
}
