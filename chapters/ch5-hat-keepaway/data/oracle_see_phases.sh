#!/bin/bash
# Issue 28: the real players' see phases. Starts the oracle's rcssserver 11.1.2 and the
# keepaway 0.6 players exactly as ../shared/oracle/keepaway/run.sh does (keepaway.sh's
# server options with synch_mode=1; three keepers at once, two seconds' sleep, two takers),
# except that every player logs its incoming messages at level 2 (-l 2 -o RUN_DIR/kN.log,
# tN.log: each cycle's "SENSE (t, s)" header and every "(see t ...)"), runs SECS seconds
# and stops. oracle_see_phases.py reads the logs.
#
# usage: oracle_see_phases.sh PORT RUN_DIR [SECS]   (ORACLE_DIR as for run.sh, default $TMPDIR/oracle)
set -u
PORT=${1:?usage: oracle_see_phases.sh PORT RUN_DIR [SECS]}
RUN_DIR=${2:?usage: oracle_see_phases.sh PORT RUN_DIR [SECS]}
SECS=${3:-30}
ORACLE_DIR=${ORACLE_DIR:-${TMPDIR:-/tmp}/oracle}
SRV=$ORACLE_DIR/build/rcssserver/rcssserver
PLY_DIR=$ORACLE_DIR/build/keepaway/player
mkdir -p "$RUN_DIR/home"
s=server
server_opts="$s::port=$PORT $s::coach_port=$((PORT+1)) $s::olcoach_port=$((PORT+2)) $s::half_time=-1 $s::forbid_kick_off_offside=0 $s::use_offside=0 $s::stamina_inc_max=3500 $s::synch_mode=1 $s::synch_offset=80 $s::keepaway=1 $s::keepaway_start=8 $s::keepaway_width=20 $s::keepaway_length=20 $s::keepaway_logging=1 $s::keepaway_log_dir=$RUN_DIR $s::keepaway_log_fixed=1 $s::keepaway_log_fixed_name=ka $s::game_logging=0 $s::text_logging=0 $s::visible_angle=360 $s::coach=0"
( cd "$RUN_DIR" && HOME=$RUN_DIR/home exec "$SRV" $server_opts ) > "$RUN_DIR/server.out" 2>&1 &
SPID=$!
sleep 2
cd "$PLY_DIR"
PIDS=""
client="-p $PORT -k 3 -j 2 -x -1 -y -1"
for i in 1 2 3; do ./keepaway_player $client -t keepers -e 0 -q hand -l 2 -o "$RUN_DIR/k$i.log" > "$RUN_DIR/k$i.out" 2>&1 & PIDS="$PIDS $!"; done
sleep 2
for i in 1 2; do ./keepaway_player $client -t takers -e 0 -q hand -l 2 -o "$RUN_DIR/t$i.log" > "$RUN_DIR/t$i.out" 2>&1 & PIDS="$PIDS $!"; done
sleep "$SECS"
kill -INT $SPID; sleep 1
for p in $PIDS; do kill "$p" 2>/dev/null; done
kill $SPID 2>/dev/null
wait 2>/dev/null
