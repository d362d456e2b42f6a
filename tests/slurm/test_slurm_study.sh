#!/usr/bin/env bash
# A design study on a real Slurm: starts a single-node cluster on this machine (munge,
# slurmctld and slurmd on localhost, as root), submits a small study as a job array
# (`filmdyn study --scheduler slurm`), waits for it, collects it, runs the same study locally and
# checks that the two study.csv tables are equal (the wall-time column aside) and every point's
# results.csv is the same byte for byte. Installs slurm-wlm and munge if missing (Debian 12).
# Usage: tests/slurm/test_slurm_study.sh [BUILD_DIR]   (CI: .ci/run)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-${FILMDYN_BUILD_DIR:-$root/build}}"
filmdyn="$build/app/filmdyn"
[ -x "$filmdyn" ] || { echo "slurm test: $filmdyn not built" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "slurm test: needs root (it starts munged, slurmctld, slurmd)" >&2; exit 1; }
start=$(date +%s)

missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "slurm test: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

work="$(mktemp -d /tmp/filmdyn-slurm.XXXXXX)"
pids=()
cleanup() {
  for f in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
  done
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  sleep 1
  rm -rf "$work"
}
trap cleanup EXIT

# munge: a key of its own, its own socket folder.
install -d -m 700 -o munge -g munge /etc/munge
if [ ! -s /etc/munge/munge.key ]; then
  dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
  chown munge:munge /etc/munge/munge.key
  chmod 400 /etc/munge/munge.key
fi
install -d -o munge -g munge /run/munge /var/lib/munge /var/log/munge
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  runuser -u munge -- /usr/sbin/munged --force
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
  if [ -s /run/munge/munged.pid ]; then pids+=("$(cat /run/munge/munged.pid)"); fi
fi
munge -n | unmunge | grep -q "STATUS: *Success" || { echo "slurm test: munge does not work" >&2; exit 1; }

# slurmd sets up its cgroup plugin at start and gives up without the machine's cgroup file
# system (a chroot needs /sys/fs/cgroup bound in): say so rather than fail in its log.
if ! mountpoint -q /sys/fs/cgroup; then
  echo "slurm test: /sys/fs/cgroup is not mounted here; slurmd cannot start without it" >&2
  exit 1
fi

host="$(hostname -s)"
mkdir -p "$work/state" "$work/spool"
export SLURM_CONF="$work/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=filmdyn-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# cgroup v2 machines: slurmd would ask systemd (over D-Bus) for a scope; our daemons are not
# systemd services, so it makes its cgroup itself (cgroup v1 machines ignore this).
cat > "$work/cgroup.conf" <<CONF
CgroupPlugin=autodetect
IgnoreSystemd=yes
CONF
slurmctld -f "$SLURM_CONF" || { echo "slurm test: slurmctld did not start"; cat "$work/slurmctld.log"; exit 1; }
slurmd -f "$SLURM_CONF" || { echo "slurm test: slurmd did not start"; cat "$work/slurmd.log"; exit 1; }
for _ in $(seq 60); do
  sinfo -h -o '%t' 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 0.5
done
sinfo -h -o '%t' | grep -qE '^(idle|mix|alloc)' || {
  echo "slurm test: the node did not come up"; sinfo || true; tail -20 "$work"/slurm*.log; exit 1; }
echo "slurm test: single-node cluster up after $(( $(date +%s) - start )) s"

# Ideal and a coarse Only-LBRBE at two speeds; two points per array task, two tasks at once.
cat > "$work/quick.json" <<'JSON'
{
  "name": "slurm-quick",
  "design": "full-factorial",
  "set": {"big_end.mesh_theta": 24, "big_end.mesh_z": 6, "solver.error_estimate": 0,
          "solver.max_cycles": 2},
  "factors": [
    {"path": "model", "levels": ["ideal", "only-lbrbe"]},
    {"path": "operating.rpm", "levels": [2000, 6000]}
  ]
}
JSON
cd "$work"
"$filmdyn" study quick.json --out on-slurm --scheduler slurm --points-per-task 2 --max-parallel 2
grep -q "^#SBATCH --array=0-1%2" on-slurm/slurm/study.sbatch
for _ in $(seq 300); do
  "$filmdyn" study status on-slurm > status.txt
  head -1 status.txt | grep -q "^4 points, 4 done$" && break
  sleep 1
done
cat status.txt
head -1 status.txt | grep -q "^4 points, 4 done$" || {
  echo "slurm test: the array did not finish"; cat on-slurm/slurm/*.out || true; exit 1; }
"$filmdyn" study collect on-slurm
"$filmdyn" study quick.json --out local --jobs 2 --quiet

# study.csv: equal but for the wall-time column (each run's own).
strip_wall_time() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time[s]") w = i }
           { out = ""; for (i = 1; i <= NF; ++i) if (i != w) out = out (out == "" ? "" : ",") $i; print out }' "$1"
}
diff <(strip_wall_time on-slurm/study.csv) <(strip_wall_time local/study.csv)
for p in point-0001 point-0002 point-0003 point-0004; do
  cmp on-slurm/$p/results.csv local/$p/results.csv
  if [ -f local/$p/motion.csv ]; then cmp on-slurm/$p/motion.csv local/$p/motion.csv; fi
done
echo "slurm test: passed in $(( $(date +%s) - start )) s (the job array's study.csv and results equal the local run's)"
