#!/usr/bin/env python3
"""How the real server's keepaway episodes end, per simulated second.

Reads a run of ../shared/oracle/keepaway/run.sh (RUN_DIR/ka.kwy and the
server text log RUN_DIR/ka.rcl) the way that directory's analyze.py does
(episode 1 dropped; commands stamped t with start <= t < end belong to the
episode; kicks in the order the server received them) and prints what the
simulator's `mechanisms` example prints for our episodes:

  endings by cause (o/t) x the team that kicked last, per simulated second;
  passes per second (keeper kick followed by another keeper's, no taker kick
  between); endings within 10 cycles of the last strong (power >= 50) keeper
  kick with no taker kick since, by cause, per second.

usage: oracle_mechanisms.py RUN_DIR N
"""
import re
import sys

CMD_RE = re.compile(r'^(\d+)(?:,\d+)?\tRecv (keepers|takers)_(\d+): (.*)$')
KICK_RE = re.compile(r'\(kick ([-0-9.e+]+) ([-0-9.e+]+)\)')


def read_episodes(run_dir, n):
    """(start, end, 'o'|'t') of episodes 2..n+1 of RUN_DIR/ka.kwy."""
    eps = []
    for line in open(run_dir + '/ka.kwy'):
        if line.startswith('#') or not line.strip():
            continue
        a = line.split()
        eps.append((int(a[1]), int(a[2]), a[4]))
    return eps[1:n + 1]


def read_kicks(run_dir):
    """(cycle, team, unum, power) of every kick command in RUN_DIR/ka.rcl,
    by cycle and, within a cycle, in the order the server received them."""
    kicks = []
    for line in open(run_dir + '/ka.rcl', errors='replace'):
        if '(kick' not in line:
            continue
        m = CMD_RE.match(line.rstrip('\n'))
        if m:
            for k in KICK_RE.finditer(m.group(4)):
                kicks.append((int(m.group(1)), m.group(2), int(m.group(3)), float(k.group(1))))
    kicks.sort(key=lambda k: k[0])  # stable: receive order within a cycle
    return kicks


def main():
    run_dir, n = sys.argv[1], int(sys.argv[2])
    eps = read_episodes(run_dir, n)
    kicks = read_kicks(run_dir)
    ends = {(h, t): 0 for h in 'ot' for t in ('keepers', 'takers', 'none')}
    lost = {'o': 0, 't': 0}
    # endings whose last cycle with a kick command had both teams' commands,
    # by cause x the team whose command arrived last in that cycle
    mixed = {(h, t): 0 for h in 'ot' for t in ('keepers', 'takers')}
    passes = 0
    cycles = 0
    ki = 0
    for st, en, how in eps:
        while ki < len(kicks) and kicks[ki][0] < st:
            ki += 1
        seq = []
        while ki < len(kicks) and kicks[ki][0] < en:
            seq.append(kicks[ki])
            ki += 1
        cycles += en - st
        last_owner = None
        strong = None
        for t, team, unum, power in seq:
            if team == 'keepers':
                if last_owner is not None and last_owner != unum:
                    passes += 1
                last_owner = unum
                if power >= 50.0:
                    strong = t
            else:
                last_owner = None
                strong = None
        last = seq[-1][1] if seq else 'none'
        ends[(how, last)] += 1
        if seq:
            final = {team for t, team, _, _ in seq if t == seq[-1][0]}
            if len(final) == 2:
                mixed[(how, last)] += 1
        if last == 'keepers' and strong is not None and en <= strong + 10:
            lost[how] += 1
    secs = cycles / 10.0
    print('episodes=%d seconds=%.1f mean_s=%.3f' % (len(eps), secs, secs / len(eps)))
    for (h, t), v in sorted(ends.items()):
        print('end_%s_last_%s count=%d per_s=%.4f' % (h, t, v, v / secs))
    print('passes count=%d per_s=%.4f' % (passes, passes / secs))
    for (h, t), v in sorted(mixed.items()):
        print('end_%s_both_teams_in_last_kick_cycle_%s_arrived_last count=%d per_s=%.4f' % (h, t, v, v / secs))
    for h in 'ot':
        k_only = ends[(h, 'keepers')] - mixed[(h, 'keepers')]
        t_only = ends[(h, 'takers')] - mixed[(h, 'takers')]
        both = mixed[(h, 'keepers')] + mixed[(h, 'takers')]
        for what, v in (('keepers_only', k_only), ('takers_only', t_only), ('both', both)):
            print('end_%s_last_kick_cycle_%s count=%d per_s=%.4f' % (h, what, v, v / secs))
    for h in 'ot':
        print('lost_after_strong_kick_%s count=%d per_s=%.4f' % (h, lost[h], lost[h] / secs))


if __name__ == '__main__':
    main()
