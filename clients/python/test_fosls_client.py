#!/usr/bin/env python3
"""fosls_client.py against a real fosls-serve started here (FOSLS_SERVE: its path; FOSLS_SOURCE:
the repository): a valid case is solved (module and program), an invalid one lists its JSON
pointers, a case without contact exits with 4, the VTU and the case come back, and a job is
cancelled and deleted."""
import io
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import unittest
from contextlib import redirect_stderr, redirect_stdout

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import fosls_client  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("FOSLS_SOURCE", HERE.parent.parent))
SERVE = os.environ.get("FOSLS_SERVE", str(SOURCE / "build" / "bin" / "fosls-serve"))


def small_case(name, refinements=1):
    case = json.loads((SOURCE / "solver/examples/signorini_square.json").read_text())
    case["name"] = name
    case["mesh"]["refinements"] = refinements
    return case


class ClientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        folder = pathlib.Path(cls.folder.name)
        cls.log = open(folder / "server.log", "w")
        cls.server = subprocess.Popen(
            [SERVE, "--port", "0", "--db", str(folder / "jobs.db"), "--workers", "1"],
            stdout=subprocess.PIPE, stderr=cls.log, text=True)
        line = cls.server.stdout.readline()
        match = re.search(r"listening on (http://\S+)", line)
        if not match:
            cls.server.kill()
            raise RuntimeError(f"fosls-serve did not start: {line!r}")
        cls.url = match.group(1)
        cls.client = fosls_client.Client(cls.url)

    @classmethod
    def tearDownClass(cls):
        cls.server.terminate()
        cls.server.wait(timeout=30)
        cls.log.close()
        cls.folder.cleanup()

    def run_program(self, case, *extra):
        path = pathlib.Path(self.folder.name) / "case.json"
        path.write_text(json.dumps(case))
        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            code = fosls_client.main([str(path), "--url", self.url, *extra])
        return code, out.getvalue(), err.getvalue()

    def test_solve_returns_the_job_and_its_result(self):
        job, result = self.client.solve(small_case("module"))
        self.assertEqual(job["state"], "succeeded")
        self.assertTrue(job["converged"])
        self.assertEqual(result["name"], "module")
        self.assertGreater(result["contact"]["force"][1], 0)
        self.assertEqual(self.client.case(job["id"])["name"], "module")
        vtu = self.client.solution_vtu(job["id"])
        self.assertTrue(vtu.startswith(b"<?xml") and b"<UnstructuredGrid>" in vtu)

    def test_the_program_prints_the_answer_and_writes_the_files(self):
        folder = pathlib.Path(self.folder.name)
        case = small_case("program")
        case["units"] = {"length": "mm", "stress": "MPa"}
        code, out, err = self.run_program(case, "--out", str(folder / "r.json"),
                                          "--vtu", str(folder / "s.vtu"))
        self.assertEqual(code, 0, err)
        result = json.loads((folder / "r.json").read_text())
        self.assertIn(f"contact width {result['contact']['zone']['length']:.4g} mm", out)
        self.assertIn("N/mm per unit thickness", out)
        self.assertTrue((folder / "s.vtu").read_bytes().startswith(b"<?xml"))

    def test_a_3d_result_is_summarised_without_2d_fields(self):
        case = json.loads((SOURCE / "solver/examples/3d/hertz_3d.json").read_text())
        case["name"] = "ball"
        case["mesh"]["refinements"] = 0
        code, out, err = self.run_program(case)
        self.assertIn(code, (0, 4), err)  # a coarse ball may be flagged for review
        self.assertIn("force [", out)
        self.assertNotIn("per unit thickness", out)
        self.assertIn("peak pressure", out)
        job, result = self.client.solve(case)
        self.assertEqual(result["dimension"], 3)
        self.assertGreater(result["contact"]["force"][2], 0)
        line = fosls_client.summary(job, result)
        if "zone" in result["contact"]:
            self.assertIn(f"contact radius {result['contact']['zone']['radius']:.4g}", line)

    def test_an_invalid_case_lists_its_pointers(self):
        case = small_case("bad")
        case["material"]["mu"] = -1
        with self.assertRaises(fosls_client.InvalidCase) as raised:
            self.client.submit(case)
        self.assertIn("/material/mu", [e["pointer"] for e in raised.exception.errors])
        code, _, err = self.run_program(case)
        self.assertEqual(code, 2)
        self.assertIn("error: /material/mu:", err)

    def test_an_answer_without_contact_exits_with_four(self):
        case = small_case("pulled away")
        case["boundary"]["top"]["displacement"] = [0, 0.05]
        code, _, err = self.run_program(case)
        self.assertEqual(code, 4, err)
        self.assertIn("warning: no contact", err)

    def test_a_job_is_cancelled_and_deleted(self):
        case = small_case("slow", refinements=6)
        # Its own time limit keeps it within the service's default --max-job-seconds.
        case["solver"] = {"method": "pgs", "tolerance": 1e-14, "max_iterations": 100000,
                          "time_limit_s": 3000}
        job = self.client.submit(case)
        self.client.cancel(job["id"])
        job = self.client.wait(self.client.job(job["id"]))
        self.assertEqual(job["state"], "cancelled")
        with self.assertRaises(fosls_client.ServiceError) as raised:
            self.client.result(job["id"])  # a cancelled job has no result
        self.assertEqual(raised.exception.status, 409)
        self.client.delete(job["id"])
        with self.assertRaises(fosls_client.ServiceError) as raised:
            self.client.job(job["id"])
        self.assertEqual(raised.exception.status, 404)


if __name__ == "__main__":
    unittest.main()
