#!/usr/bin/env python3
"""The service's machine-readable contract against a real fosls-serve.

- GET /v1/openapi.json is OpenAPI 3.1; its case and result schemas are the generated ones
  (docs/schemas, equal byte for byte to what /v1/schemas serves), so they cannot drift.
- Its routes are exactly the routes of docs/service.md's API table, and each one, called on
  the server, answers with a status the document lists for it; every job the server returns
  is valid for the document's Job schema, every result for the result schema.
- GET /v1/jobs/{id}/case returns the submitted case.
- The Python client (clients/python/fosls_client.py) runs against the server: a valid case
  prints its answer, an invalid one lists its JSON pointers.
"""
import argparse
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

try:
    import jsonschema
    from referencing import Registry
    from referencing.jsonschema import DRAFT202012
except ImportError:
    sys.exit("python3-jsonschema is missing: install it (docker/install-deps.sh does)")


class Server:
    """fosls-serve on a free loopback port with a temporary database."""

    def __init__(self, serve, folder):
        self.process = subprocess.Popen(
            [serve, "--port", "0", "--db", str(folder / "jobs.db"), "--workers", "1"],
            stdout=subprocess.PIPE, stderr=open(folder / "server.log", "w"), text=True)
        line = self.process.stdout.readline()
        match = re.search(r"listening on (http://\S+)", line)
        if not match:
            self.process.kill()
            sys.exit(f"fosls-serve did not start: {line!r}")
        self.url = match.group(1)

    def call(self, method, path, body=None):
        data = None if body is None else json.dumps(body).encode()
        headers = {"Content-Type": "application/json"} if data is not None else {}
        request = urllib.request.Request(self.url + path, data=data, method=method, headers=headers)
        try:
            with urllib.request.urlopen(request, timeout=60) as response:
                return response.status, response.headers.get("Content-Type"), response.read()
        except urllib.error.HTTPError as e:
            return e.code, e.headers.get("Content-Type"), e.read()

    def json(self, path):
        status, _, body = self.call("GET", path)
        assert status == 200, (path, status, body[:300])
        return json.loads(body)

    def wait_finished(self, job_id):
        for _ in range(6000):  # bounds a broken server; no time is asserted
            job = self.json(f"/v1/jobs/{job_id}")
            if job["state"] not in ("queued", "running"):
                return job
            time.sleep(0.02)
        raise AssertionError(f"job {job_id} did not finish")

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=30)


def small_case(source, name):
    case = json.loads((source / "solver/examples/signorini_square.json").read_text())
    case["name"] = name
    case["mesh"]["refinements"] = 1
    return case


def documented_routes(source):
    """(method, path) of every row of the API table in docs/service.md, static files aside."""
    routes = set()
    for line in (source / "docs/service.md").read_text().splitlines():
        for method, path in re.findall(r"`(GET|POST|DELETE|PUT|PATCH) (/[^`?\s]*)", line):
            if line.startswith("| `") and path not in ("/", "/<file>"):
                routes.add((method, path))
    return routes


def check_document(server, source, failures):
    doc = server.json("/v1/openapi.json")
    if doc.get("openapi") != "3.1.0":
        failures.append(f"openapi is {doc.get('openapi')!r}, not 3.1.0")
    for name in ("case", "result"):
        served = server.json(f"/v1/schemas/{name}.json")
        published = json.loads((source / f"docs/schemas/{name}.schema.json").read_text())
        if served != published:
            failures.append(f"/v1/schemas/{name}.json differs from docs/schemas/{name}.schema.json")
    in_document = {(m.upper(), p) for p, ops in doc["paths"].items() for m in ops}
    in_docs = documented_routes(source)
    for route in sorted(in_docs - in_document):
        failures.append(f"{route} is in docs/service.md but not in the OpenAPI document")
    for route in sorted(in_document - in_docs):
        failures.append(f"{route} is in the OpenAPI document but not in docs/service.md")
    return doc


def validators(server, doc):
    """Validators for the document's Job schema and the result schema, $refs resolved."""
    resources = [(server.url + "/v1/openapi.json", DRAFT202012.create_resource(doc))]
    for name in ("case", "result"):
        schema = server.json(f"/v1/schemas/{name}.json")
        resources.append((server.url + f"/v1/schemas/{name}.json",
                          DRAFT202012.create_resource(schema)))
    registry = Registry().with_resources(resources)
    job = jsonschema.Draft202012Validator(
        {"$ref": server.url + "/v1/openapi.json#/components/schemas/Job"}, registry=registry)
    result = jsonschema.Draft202012Validator(server.json("/v1/schemas/result.json"))
    return job, result


def check_operations(server, source, doc, failures):
    """Calls every operation of the document; each answer's status must be listed for it."""
    job_validator, result_validator = validators(server, doc)
    case = small_case(source, "contract")
    status, _, body = server.call("POST", "/v1/jobs", case)
    assert status == 202, body
    job_id = json.loads(body)["id"]
    done = server.wait_finished(job_id)
    for error in job_validator.iter_errors(done):
        failures.append(f"job JSON not valid for the Job schema: {error.message}")
    if done["converged"] is not True or done["stop_reason"] != "converged":
        failures.append(f"job {job_id}: converged {done['converged']}, {done['stop_reason']}")
    for error in result_validator.iter_errors(server.json(f"/v1/jobs/{job_id}/result")):
        failures.append(f"result not valid for the result schema: {error.message}")
    if server.json(f"/v1/jobs/{job_id}/case") != case:
        failures.append("GET /v1/jobs/{id}/case does not return the submitted case")

    # Deleting last, so the other calls see the finished job.
    order = sorted(((p, m) for p, ops in doc["paths"].items() for m in ops),
                   key=lambda pm: pm[1] == "delete")
    for path, method in order:
        for target in (job_id, 999999) if "{id}" in path else (None,):
            concrete = path.replace("{id}", str(target))
            body = case if (method, path) == ("post", "/v1/jobs") else None
            status, content_type, text = server.call(method.upper(), concrete, body)
            listed = doc["paths"][path][method]["responses"]
            if str(status) not in listed:
                failures.append(f"{method.upper()} {concrete} answered {status}, the document "
                                f"lists {sorted(listed)}")
            elif 200 <= status < 300 and (content_type or "").startswith("application/json"):
                payload = json.loads(text)
                if "/v1/jobs/{id}" == path or "cancel" in path or method == "post":
                    for error in job_validator.iter_errors(payload):
                        failures.append(f"{method.upper()} {concrete}: {error.message}")


def check_client(server, source, folder, failures):
    client = source / "clients/python/fosls_client.py"
    good = folder / "good.json"
    good.write_text(json.dumps(small_case(source, "from-the-client")))
    bad_case = small_case(source, "bad")
    bad_case["material"]["mu"] = -1
    bad = folder / "bad.json"
    bad.write_text(json.dumps(bad_case))
    env = dict(os.environ, FOSLS_URL=server.url)
    run = subprocess.run([sys.executable, str(client), str(good)], env=env, capture_output=True,
                         text=True, timeout=300)
    if run.returncode != 0 or not re.search(r"converged .*force", run.stdout):
        failures.append(f"the example client on a valid case: exit {run.returncode}, "
                        f"stdout {run.stdout!r}, stderr {run.stderr!r}")
    run = subprocess.run([sys.executable, str(client), str(bad)], env=env, capture_output=True,
                         text=True, timeout=60)
    if run.returncode != 2 or "/material/mu" not in run.stderr:
        failures.append(f"the example client on an invalid case: exit {run.returncode}, "
                        f"stderr {run.stderr!r}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--serve", required=True)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    source = pathlib.Path(args.source)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        server = Server(args.serve, folder)
        try:
            doc = check_document(server, source, failures)
            check_operations(server, source, doc, failures)
            check_client(server, source, folder, failures)
        finally:
            server.stop()
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
