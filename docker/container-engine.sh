# Sourced by docker/build-image.sh and docker/test-image.sh: which container engine to use
# and how to call it on this machine.
#
# Docker where a Docker engine answers (`docker info`), podman otherwise (FOSLS_ENGINE=podman
# or =docker chooses). Podman runs with runc: crun fails on the cgroup setup of some virtual
# machines (cgroup v1 without systemd). Neither runtime raises a resource limit above the one
# of the process that starts it: podman's default open-file limit (1048576) is above the
# hard limit of such machines, and podman's conmon runs with at most 32768 processes. So
# containers get the host's open-file limits and at most 4096 processes (`engine_run_args`,
# the arguments of `run` on this machine).

# Installs what is missing for podman (quietly; nothing when Docker is used).
select_container_engine() {
  local here
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  case "${FOSLS_ENGINE:-}" in
    docker | podman) engine_name="${FOSLS_ENGINE}" ;;
    "")
      if command -v docker >/dev/null && docker info >/dev/null 2>&1; then
        engine_name=docker
      else
        engine_name=podman
      fi
      ;;
    *)
      echo "FOSLS_ENGINE must be docker or podman, not '${FOSLS_ENGINE}'" >&2
      return 2
      ;;
  esac
  if [[ "${engine_name}" == docker ]]; then
    engine=(docker)
    engine_run_args=()
    return 0
  fi
  "${here}/install-deps.sh" --container
  engine=(podman --runtime runc)
  engine_run_args=(--ulimit "nofile=$(limit_pair n 1048576)" --ulimit "nproc=$(limit_pair u 4096)")
}

# "soft:hard" of the current shell's limit (ulimit -n / -u), each at most CAP.
limit_pair() { # n|u CAP
  local soft hard
  soft="$(ulimit -S"$1")"
  hard="$(ulimit -H"$1")"
  [[ "${soft}" == unlimited || "${soft}" -gt "$2" ]] && soft="$2"
  [[ "${hard}" == unlimited || "${hard}" -gt "$2" ]] && hard="$2"
  echo "${soft}:${hard}"
}

# The base image the Dockerfiles start from (FROM debian:12-slim). When it is missing and
# podman is used, it is made from Debian's packages, with no image registry: mmdebstrap
# installs the minimal Debian 12 (apt and the essential packages) into a tar file, without
# manual pages, documentation and translations, as Debian's own slim images; the dpkg
# setting stays in the image, so later apt-get installs in it skip them too.
base_image=docker.io/library/debian:12-slim
ensure_base_image() {
  if [[ "${engine_name}" == docker ]] || "${engine[@]}" image inspect "${base_image}" >/dev/null 2>&1; then
    return 0 # present, or docker build pulls it
  fi
  local scratch
  scratch="$(mktemp -d)"
  echo "making ${base_image} from Debian's packages (mmdebstrap, about 2 minutes)"
  mmdebstrap --quiet --variant=minbase \
    --dpkgopt='path-exclude=/usr/share/man/*' \
    --dpkgopt='path-exclude=/usr/share/doc/*' \
    --dpkgopt='path-include=/usr/share/doc/*/copyright' \
    --dpkgopt='path-exclude=/usr/share/locale/*' \
    --dpkgopt='path-exclude=/usr/share/info/*' \
    bookworm "${scratch}/rootfs.tar"
  "${engine[@]}" import --quiet "${scratch}/rootfs.tar" "${base_image}" >/dev/null
  rm -rf "${scratch}"
}
