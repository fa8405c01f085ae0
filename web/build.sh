#!/usr/bin/env bash
# Prepares the web page for fosls-serve: installs the npm packages pinned in
# package-lock.json and fills web/dist/ (gitignored) with what the browser loads besides
# our own files:
#   dist/uPlot.esm.js, dist/uPlot.min.css   the plotting library, copied from node_modules
#   dist/examples.json                      the shipped cases (solver/examples/*.json, then
#                                           solver/examples/3d/*.json)
# Idempotent: npm ci runs only when the lock file changed since the last install.
#
#   web/build.sh            # everything, including playwright-core for the browser test
#   web/build.sh --runtime  # only what the page needs (e.g. in a container image)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
examples_dir="${here}/../solver/examples"
cd "${here}"

omit_dev=()
if [[ "${1:-}" == "--runtime" ]]; then
  omit_dev=(--omit=dev)
elif [[ $# -gt 0 ]]; then
  echo "usage: web/build.sh [--runtime]" >&2
  exit 2
fi

command -v npm >/dev/null || { echo "web/build.sh: npm is missing (apt-get install npm)" >&2; exit 1; }

# npm ci deletes node_modules and reinstalls; skip it when the installed tree matches the lock.
stamp="node_modules/.fosls-lock-stamp"
want="$(sha256sum package-lock.json | cut -d' ' -f1) ${omit_dev[*]:-all}"
if [[ ! -f "${stamp}" || "$(cat "${stamp}")" != "${want}" ]]; then
  npm ci --no-audit --no-fund --loglevel=error "${omit_dev[@]}"
  echo "${want}" > "${stamp}"
fi

mkdir -p dist
install -m 0644 node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css dist/
node scripts/make_examples.mjs "${examples_dir}" dist/examples.json
