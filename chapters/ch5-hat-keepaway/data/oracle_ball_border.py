#!/usr/bin/env python3
"""Where the ball is in the real server's keepaway episodes, as the distance
from the region's nearest border: the lines the simulator's `ball_border`
example prints for our episodes (shares of cycles, of keeper kicks and of
taker kicks per distance bin, and of the last kicking cycle of the episodes
that end out after a cycle in which only takers kicked).

Reads a run of ../shared/oracle/keepaway/run.sh made with the game log on,
e.g.

  EXTRA_SERVER_OPTS=server::game_logging=1 NK=4 NT=3 SIDE=25 run.sh hand 1000

(with run.sh's -k/-j and region set from NK, NT, SIDE as in the oracle's
configuration runs): RUN_DIR/ka.rcg (rcssserver 11's binary game log,
version 3: the ball's and players' positions every cycle), with ka.kwy and
ka.rcl read as oracle_mechanisms.py reads them. The record sizes are those
of rcssserver 11.1.2's structs on x86-64 (types.h: short_showinfo_t2 1,428
bytes, server_params_t 396, player_params_t 132, player_type_t 88).

usage: oracle_ball_border.py RUN_DIR N SIDE
"""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle_mechanisms import read_episodes, read_kicks  # noqa: E402

SHOW, MSG = 1, 2
SIZES = {1: 1428, 3: None, 4: 0, 5: 1, 6: 36, 7: 88, 8: 396, 9: 132}
SCALE = 65536.0
BINS = [0.0, 1.0, 2.0, 3.0, 5.0, 8.0, 13.0]


def read_ball(path):
    """{cycle: (x, y)} of the ball from a version-3 game log; the log's
    16-bit times unwrapped."""
    data = open(path, 'rb').read()
    if data[:3] != b'ULG' or data[3] != 3:
        sys.exit('%s: not a version 3 rcssserver game log' % path)
    i, ball, last, base = 4, {}, None, 0
    while i + 2 <= len(data):
        mode = struct.unpack_from('>h', data, i)[0]
        i += 2
        if mode == MSG:
            _, n = struct.unpack_from('>hh', data, i)
            i += 4 + n
            continue
        size = SIZES.get(mode)
        if size is None:
            sys.exit('%s: record mode %d at byte %d is not read here' % (path, mode, i - 2))
        if mode == SHOW:
            bx, by = struct.unpack_from('>ii', data, i)
            t = struct.unpack_from('>H', data, i + 1424)[0]
            if last is not None and t + base < last - 30000:
                base += 65536
            last = t + base
            ball[last] = (bx / SCALE, by / SCALE)
        i += size
    return ball


def shares(xs):
    c = [0] * len(BINS)
    for x in xs:
        c[max(j for j, b in enumerate(BINS) if x >= b or j == 0)] += 1
    return ' '.join('%.3f' % (v / max(1, len(xs))) for v in c)


def main():
    run_dir, n, side = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    half = side / 2.0
    eps = read_episodes(run_dir, n)
    ball = read_ball(run_dir + '/ka.rcg')
    teams_at = {}
    for t, team, _, _ in read_kicks(run_dir):
        teams_at.setdefault(t, set()).add(team)

    def border(b):
        return min(half - abs(b[0]), half - abs(b[1]))

    cycles, keeper_kicks, taker_kicks, takers_only_outs = [], [], [], []
    missing = 0
    for st, en, how in eps:
        last = None
        for t in range(st, en):
            if t not in ball:
                missing += 1
                continue
            d = border(ball[t])
            cycles.append(d)
            teams = teams_at.get(t, ())
            keeper_kicks += [d] * ('keepers' in teams)
            taker_kicks += [d] * ('takers' in teams)
            if teams:
                last = (t, teams)
        if how == 'o' and last is not None and last[1] == {'takers'}:
            takers_only_outs.append(border(ball[last[0]]))
    if missing:
        print('warning: %d cycles of the episodes have no position in the game log' % missing)
    print('bins (m from the border, lower edges) %s' % BINS)
    print('cycles %d' % len(cycles))
    print('all cycles       %s' % shares(cycles))
    print('keeper kicks     %d %s' % (len(keeper_kicks), shares(keeper_kicks)))
    print('taker kicks      %d %s' % (len(taker_kicks), shares(taker_kicks)))
    print('takers-only outs %d %s' % (len(takers_only_outs), shares(takers_only_outs)))


if __name__ == '__main__':
    main()
