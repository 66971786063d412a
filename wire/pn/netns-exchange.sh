#!/usr/bin/env bash
# One PROFINET exchange between two network namespaces of this run's own:
# the device (pn-device, built from the layouts) in one, the IO controller
# (pn_controller.py on profinet-py, reading only the GSDML) in the other,
# joined by a veth pair that exists only inside them. Nothing is sent on any
# other interface: both ends are created inside the namespaces, and deleting
# a namespace deletes its end. Needs root.
#
#   wire/pn/netns-exchange.sh DEVICE PYTHON CARD GSDML STATION SLOT MODULE NAME SCENARIO|- [--also SLOT MODULE NAME]... [DEVICE_FLAGS...]
#
# DEVICE: the pn-device binary; PYTHON: the venv's python with profinet-py;
# CARD: the description's name in the firmware; STATION: the name of
# station both ends use; MODULE: the GSDML's ModuleItem ID, plugged in SLOT,
# and NAME its name, by which the device finds it in its layout (each
# --also plugs another module in another slot at the same time); SCENARIO:
# the manual's checks (JSON) or -. DEVICE_FLAGS go to the device
# (--mismatch KIND makes it a negative case, and the controller then expects
# the Connect refused; --dap N makes it present device access point N in
# slot 0, and the controller connects with the GSDML's Nth, or with
# --controller-dap M, which is the controller's alone, its Mth: one of N's
# ident number). The device takes its name of station from its
# layout; the controller finds it by the GSDML's (STATION), so the two must
# agree.
#
# SCENARIO soft-card runs the soft card's command instead (README: no
# --seconds, it runs until stopped): the controller DCP-identifies it by the
# GSDML's name of station, then SIGINT (Ctrl-C) must stop it, exit 0, within
# 5 s; started again, SIGTERM must too.
#
# Exit status: the controller's (0 passed, 1 failed, 2 could not run); 2
# also when the namespaces cannot be made. The namespaces carry this
# script's process id, so runs side by side do not meet; every exit path
# kills the device by its process id and deletes both namespaces.
set -euo pipefail
[ $# -ge 9 ] || { echo "usage: $0 DEVICE PYTHON CARD GSDML STATION SLOT MODULE NAME SCENARIO|- [DEVICE_FLAGS...]" >&2; exit 2; }
device=$1 python=$2 card=$3 gsdml=$4 station=$5 slot=$6 module=$7 name=$8 scenario=$9
shift 9
# Each --also: the device plugs the module by its name, the controller by
# its ID.
plugs=(--plug "$slot=$name")
also=()
while [ "${1:-}" = --also ]; do
  [ $# -ge 4 ] || { echo "$0: --also takes SLOT MODULE NAME" >&2; exit 2; }
  plugs+=(--plug "$2=$4")
  also+=(--also "$2=$3")
  shift 4
done
here=$(cd "$(dirname "$0")" && pwd)

ns_ctl="gsdc-pn-$$-ctl"
ns_dev="gsdc-pn-$$-dev"
# Addresses from TEST-NET-1 (RFC 5737), reserved for documentation: they
# exist only inside the two namespaces.
ip_ctl=192.0.2.1
ip_dev=192.0.2.2
work=$(mktemp -d)
device_pid=""

cleanup() {
  if [ -n "$device_pid" ]; then
    kill "$device_pid" 2>/dev/null || true
    wait "$device_pid" 2>/dev/null || true
  fi
  ip netns del "$ns_ctl" 2>/dev/null || true
  ip netns del "$ns_dev" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 2' INT TERM HUP

if ! ip netns add "$ns_ctl" || ! ip netns add "$ns_dev"; then
  echo "cannot make network namespaces (root and iproute2 needed)" >&2
  exit 2
fi
ip -n "$ns_ctl" link add pn0 type veth peer name pn0 netns "$ns_dev"
for ns in "$ns_ctl" "$ns_dev"; do
  # No IPv6 (router solicitations, DAD) on the link: only what the test sends.
  ip netns exec "$ns" sysctl -qw net.ipv6.conf.all.disable_ipv6=1 net.ipv6.conf.default.disable_ipv6=1
  ip -n "$ns" link set lo up
done
ip -n "$ns_ctl" addr add "$ip_ctl/24" dev pn0
ip -n "$ns_dev" addr add "$ip_dev/24" dev pn0
ip -n "$ns_ctl" link set pn0 up
ip -n "$ns_dev" link set pn0 up

events="$work/device-events.jsonl"
# Starts the device (with FLAGS) and waits until it listens (its first
# event), at most 5 s.
start_device() { # FLAGS...
  : >"$events"
  ip netns exec "$ns_dev" "$device" --card "$card" --iface pn0 --ip "$ip_dev" \
    "${plugs[@]}" "$@" >"$events" 2>"$work/device.err" &
  device_pid=$!
  for _ in $(seq 50); do
    [ -s "$events" ] && break
    kill -0 "$device_pid" 2>/dev/null || break
    sleep 0.1
  done
  if ! [ -s "$events" ]; then
    echo "the device did not start:" >&2
    cat "$work/device.err" >&2
    exit 2
  fi
}

# The soft card stops on SIGNAL within 5 s, exit 0, and says so.
stops_on() { # SIGNAL
  local code=0
  kill -s "$1" "$device_pid"
  for _ in $(seq 50); do
    kill -0 "$device_pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$device_pid" 2>/dev/null; then
    echo "FAIL soft card: still running 5 s after SIG$1"
    return 1
  fi
  wait "$device_pid" || code=$?
  device_pid=""
  if [ "$code" -ne 0 ] || ! tail -n 1 "$events" | grep -q "\"event\":\"stopped\",\"by\":\"SIG$1\""; then
    echo "FAIL soft card: on SIG$1 it exited $code, its last event: $(tail -n 1 "$events")"
    return 1
  fi
  echo "  soft card: stopped on SIG$1, exit 0"
}

if [ "$scenario" = soft-card ]; then
  start_device "$@"
  status=0
  timeout 30 ip netns exec "$ns_ctl" "$python" "$here/controller/pn_controller.py" \
    --identify --iface pn0 --gsdml "$gsdml" || status=$?
  [ "$status" -eq 124 ] && { echo "FAIL soft card: DCP Identify did not finish in 30 s"; status=1; }
  [ "$status" -eq 0 ] && { stops_on INT || status=1; }
  if [ "$status" -eq 0 ]; then
    start_device "$@"
    stops_on TERM || status=1
  fi
  [ "$status" -eq 0 ] || cat "$events" "$work/device.err" >&2
  exit "$status"
fi

controller_dap=""
device_flags=()
while [ $# -gt 0 ]; do
  if [ "$1" = --controller-dap ]; then
    controller_dap=$2
    shift 2
  else
    device_flags+=("$1")
    shift
  fi
done
set -- "${device_flags[@]}"
# The device stops by itself after 60 s if nothing else stops it.
start_device --seconds 60 "$@"

controller_flags=()
[ "$scenario" != "-" ] && controller_flags+=(--scenario "$scenario")
# A negative case: the PNIO status the Connect must be refused with. pnio
# numbers its ExpectedSubmodule refusals 04 (module ident) and 07 (missing
# submodule or wrong length); 05 (API) is the device's own (src/tap.rs).
previous=""
for flag in "$@"; do
  if [ "$previous" = "--mismatch" ]; then
    case "$flag" in
      module-ident) controller_flags+=(--expect-refusal DB810304) ;;
      input-length) controller_flags+=(--expect-refusal DB810307) ;;
      api) controller_flags+=(--expect-refusal DB810305) ;;
    esac
  fi
  # The device access point the device presents is the one to connect
  # with, unless --controller-dap names another of its ident number.
  [ "$previous" = "--dap" ] && controller_flags+=(--dap "${controller_dap:-$flag}")
  previous=$flag
done
status=0
timeout 30 ip netns exec "$ns_ctl" "$python" "$here/controller/pn_controller.py" \
  --iface pn0 --station "$station" --gsdml "$gsdml" --slot "$slot" --module "$module" \
  --device-events "$events" "${also[@]}" "${controller_flags[@]}" || status=$?
case "$status" in
  0 | 1) ;;
  124) echo "FAIL $module: the controller did not finish in 30 s"; status=1 ;;
  *) status=2 ;;
esac
if [ "$status" -ne 0 ]; then
  echo "the device's account:" >&2
  cat "$events" "$work/device.err" >&2
fi
exit "$status"
