#!/bin/sh
# Creates the database cluster in $PGDATA on first start (superuser $POSTGRES_USER with
# $POSTGRES_PASSWORD, database $POSTGRES_DB, password logins from any address), then runs
# the server in the foreground, listening on all addresses of the container.
set -eu
: "${POSTGRES_USER:=postgres}" "${POSTGRES_DB:=${POSTGRES_USER}}"
if [ -z "${POSTGRES_PASSWORD:-}" ]; then
  echo "fosls-postgres: set POSTGRES_PASSWORD" >&2
  exit 1
fi
if [ ! -s "${PGDATA}/PG_VERSION" ]; then
  pwfile="$(mktemp)"
  printf '%s\n' "${POSTGRES_PASSWORD}" > "${pwfile}"
  initdb --pgdata="${PGDATA}" --username="${POSTGRES_USER}" --pwfile="${pwfile}" \
    --auth-local=trust --auth-host=scram-sha-256 --encoding=UTF8 --no-instructions >/dev/null
  rm -f "${pwfile}"
  echo "host all all all scram-sha-256" >> "${PGDATA}/pg_hba.conf"
  if [ "${POSTGRES_DB}" != postgres ]; then
    pg_ctl --pgdata="${PGDATA}" --silent --wait -o "-c listen_addresses=''" start
    createdb --username="${POSTGRES_USER}" "${POSTGRES_DB}"
    pg_ctl --pgdata="${PGDATA}" --silent --wait --mode=fast stop
  fi
  echo "fosls-postgres: created the cluster in ${PGDATA}"
fi
exec postgres -D "${PGDATA}" -c listen_addresses='*' "$@"
