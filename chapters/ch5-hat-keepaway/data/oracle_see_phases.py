#!/usr/bin/env python3
"""Each real player's see phase, from its own log (issue 28).

Reads the players' level-2 logs written by oracle_see_phases.sh: every
"SENSE (t, s)" header opens a server cycle (play-on cycles have s = 0), and
every "(see t ...)" line is a see message that arrived in it; an "incoming
think message" line before a see means the see came after the cycle's think.
The simulator's model (rlfd_keepaway::SeePhases) says every player sees in two
cycles of three, skipping the cycles of one residue mod 3 set when it
connected, never after the think, and that keepaway.sh's start order gives
the three keepers one phase and the two takers one.

usage: oracle_see_phases.py RUN_DIR [RUN_DIR ...]
prints, per run and player, the share of play-on cycles with a see for each
cycle residue mod 3, the residue without sees, and the sees after a think.
"""
import re
import sys
from collections import Counter

SENSE_RE = re.compile(r'SENSE \((\d+), (\d+)\)')
PLAYERS = ['k1', 'k2', 'k3', 't1', 't2']


def player(path):
    cycle, think = None, False
    sees, late = {}, 0
    with open(path, errors='replace') as f:
        for line in f:
            m = SENSE_RE.search(line)
            if m:
                t, stopped = int(m.group(1)), int(m.group(2))
                cycle = t if stopped == 0 and t > 0 else None
                think = False
                if cycle is not None:
                    sees.setdefault(cycle, 0)
                continue
            if cycle is None:
                continue
            if 'incoming think' in line:
                think = True
            elif '(see ' in line:
                sees[cycle] += 1
                late += think
    with_see, total = Counter(), Counter()
    for c, n in sees.items():
        total[c % 3] += 1
        with_see[c % 3] += n > 0
    share = [with_see[r] / total[r] if total[r] else float('nan') for r in range(3)]
    return len(sees), share, min(range(3), key=lambda r: share[r]), late


def main():
    for run in sys.argv[1:]:
        print(run)
        for who in PLAYERS:
            n, share, skip, late = player(f'{run}/{who}.log')
            print(f'  {who}: {n} play-on cycles; share with a see by cycle mod 3: '
                  + ' '.join(f'{s:.2f}' for s in share)
                  + f'; no see in cycles = {skip} mod 3; sees after think: {late}')


if __name__ == '__main__':
    main()
