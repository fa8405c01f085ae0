#!/usr/bin/env python3
"""A client of the fosls-serve job API (docs/service.md), standard library only (Python 3.9+).

As a program:

    python3 fosls_client.py case.json [--url URL] [--out result.json] [--vtu solution.vtu]

submits the case, waits for the job, prints the answer and the result's warnings, and exits with
the codes of `fosls-contact solve`: 0 converged, 2 invalid case (every problem with its JSON
pointer), 3 not converged, 4 converged but the answer needs review (the result's
review_required: no contact, an initial overlap, implausible units), 1 anything else. The URL
defaults to $FOSLS_URL, else http://127.0.0.1:8080.

As a module:

    from fosls_client import Client
    client = Client("http://127.0.0.1:8080")
    job, result = client.solve(case)          # raises InvalidCase, JobFailed
"""
import argparse
import json
import os
import sys
import time
import urllib.error
import urllib.request

DEFAULT_URL = "http://127.0.0.1:8080"


class ServiceError(Exception):
    """An answer the client did not expect: the status and the service's problem (RFC 9457)."""

    def __init__(self, status, problem):
        detail = problem.get("detail", problem) if isinstance(problem, dict) else problem
        super().__init__(f"{status}: {detail}")
        self.status = status
        self.problem = problem


class InvalidCase(ServiceError):
    """The service refused the case (422); `errors` is its [{pointer, detail}] list."""

    def __init__(self, status, problem):
        super().__init__(status, problem)
        self.errors = problem.get("errors", [])


class JobFailed(Exception):
    """The job ended failed or cancelled; `job` is the job resource."""

    def __init__(self, job):
        super().__init__(f"job {job['id']} {job['state']}: {job.get('error')}")
        self.job = job


class Client:
    """The job API of one fosls-serve: submit, poll, fetch, cancel, delete."""

    def __init__(self, url=None, timeout=60):
        self.url = (url or os.environ.get("FOSLS_URL") or DEFAULT_URL).rstrip("/")
        self.timeout = timeout

    def call(self, method, path, body=None, raw=False):
        """(status, body): JSON bodies parsed (problems are JSON too), raw bytes with raw=True."""
        data = None if body is None else json.dumps(body).encode()
        headers = {"Content-Type": "application/json"} if data is not None else {}
        request = urllib.request.Request(self.url + path, data=data, method=method,
                                         headers=headers)
        try:
            with urllib.request.urlopen(request, timeout=self.timeout) as response:
                payload = response.read()
                return response.status, payload if raw else json.loads(payload or b"null")
        except urllib.error.HTTPError as error:
            payload = error.read()
            try:
                return error.code, json.loads(payload)
            except ValueError:
                return error.code, {"detail": payload.decode(errors="replace")}

    def submit(self, case):
        """POST /v1/jobs: the queued job; InvalidCase for a 422."""
        status, job = self.call("POST", "/v1/jobs", case)
        if status == 422:
            raise InvalidCase(status, job)
        if status not in (200, 202):
            raise ServiceError(status, job)
        return job

    def job(self, job_id):
        return self._get(f"/v1/jobs/{job_id}")

    def wait(self, job, poll_seconds=0.2):
        """Polls a job until it is no longer queued or running."""
        while job["state"] in ("queued", "running"):
            time.sleep(poll_seconds)
            job = self._get(job["links"]["self"])
        return job

    def result(self, job_id):
        return self._get(f"/v1/jobs/{job_id}/result")

    def solution_vtu(self, job_id):
        """The VTU file of a finished job, as bytes (docs/result-format.md)."""
        status, body = self.call("GET", f"/v1/jobs/{job_id}/solution.vtu", raw=True)
        if status != 200:
            raise ServiceError(status, body)
        return body

    def case(self, job_id):
        return self._get(f"/v1/jobs/{job_id}/case")

    def cancel(self, job_id):
        status, job = self.call("POST", f"/v1/jobs/{job_id}/cancel")
        if status not in (200, 202):
            raise ServiceError(status, job)
        return job

    def delete(self, job_id):
        status, body = self.call("DELETE", f"/v1/jobs/{job_id}")
        if status not in (200, 204):
            raise ServiceError(status, body)

    def solve(self, case, poll_seconds=0.2):
        """Submits, waits and fetches: (job, result). JobFailed when the job has no result."""
        job = self.wait(self.submit(case), poll_seconds)
        if job["state"] != "succeeded":
            raise JobFailed(job)
        return job, self._get(job["links"]["result"])

    def _get(self, path):
        status, body = self.call("GET", path)
        if status != 200:
            raise ServiceError(status, body)
        return body


def summary(job, result):
    """The answer in one line, in the case's declared units when it has them. A 2D result gives
    the force per unit thickness and the contact width, a 3D result (dimension 3) the force and
    the contact zone's radius; the zone's figures are left out where the result has none."""
    contact = result["contact"]
    units = result.get("units") or {}
    declared = bool(units.get("declared"))
    three = result.get("dimension") == 3
    state = "converged" if job["converged"] else "NOT converged"
    if three:
        force_unit = f" {units['force']}" if declared and units.get("force") else ""
        force = f"force {contact['force']}{force_unit}"
    else:
        force_unit = f" {units['force_per_thickness']}" if declared else ""
        force = f"force {contact['force']}{force_unit} per unit thickness"
    parts = [f"job {job['id']}: {state} ({job['stop_reason']}, {result['iterations']} iterations)",
             force]
    zone = contact.get("zone") or {}
    peak = zone.get("peak_pressure", contact.get("max_pressure"))
    if peak is not None:
        parts.append(f"peak pressure {peak:.4g}")
    length = f" {units['length']}" if declared and units.get("length") else ""
    if three and zone.get("radius") is not None:
        parts.append(f"contact radius {zone['radius']:.4g}{length}")
    elif not three and zone.get("length") is not None:
        parts.append(f"contact width {zone['length']:.4g}{length}")
    return ", ".join(parts)


def exit_code(job, result):
    if not job["converged"]:
        return 3
    return 4 if result.get("review_required") else 0


def main(argv=None):
    parser = argparse.ArgumentParser(description="Solve a case on a fosls-serve.")
    parser.add_argument("case", help="the case JSON file (- reads standard input)")
    parser.add_argument("--url", help=f"the service (default $FOSLS_URL or {DEFAULT_URL})")
    parser.add_argument("--out", help="write the result JSON here")
    parser.add_argument("--vtu", help="write the solution's VTU file here")
    args = parser.parse_args(argv)
    with (sys.stdin if args.case == "-" else open(args.case)) as f:
        case = json.load(f)
    client = Client(args.url)
    try:
        job, result = client.solve(case)
    except InvalidCase as e:
        for problem in e.errors:
            print(f"error: {problem['pointer']}: {problem['detail']}", file=sys.stderr)
        return 2
    except JobFailed as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    except (ServiceError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    if args.out:
        with open(args.out, "w") as f:
            json.dump(result, f, indent=2)
    if args.vtu:
        with open(args.vtu, "wb") as f:
            f.write(client.solution_vtu(job["id"]))
    for warning in result.get("warnings", []):
        print(f"warning: {warning}", file=sys.stderr)
    print(summary(job, result))
    return exit_code(job, result)


if __name__ == "__main__":
    sys.exit(main())
