#!/usr/bin/python3
"""Strong scaling of a case to more ranks, estimated from its partition and its measured parts.

The explicit step on N ranks, per step, as the sum of
  - the element loop and the nodal update: their rank-seconds on 2 ranks (summed
    over the ranks) divided by N, the loop times the largest rank's cell work
    over the mean (work_max_over_mean of partition_counts: the weights of
    include/wheelrail/mesh/partition_weights.h; 1 where the counts have no
    such column), the update times the largest over the mean owned nodes;
  - the contact's computed slaves: their rank-seconds divided by N (each rank
    computes a block of them);
  - the contact's replicated part (the positions of all candidates, the
    exchange of the blocks' states, the totals and nodal forces, the search):
    every rank does all of it, so it stays what one rank took on 2 ranks;
  - the messages: per step 3 exchanges with each neighbour rank (the ghosts of
    u and v, the forces; a message each way), their bytes (the largest rank's
    ghost nodes, 24 B each, 3 times) and the collectives (the contact's 6 and
    the wheelset's sum), each collective log2(N) rounds.
The partition (neighbour ranks, owned nodes) comes from bench/partition_counts
(build/partition_counts CASE.prm 2 4 ... 64 > counts.csv), the part times from a
run's split on 2 ranks, the latencies from build/mpi_exchange on this host.
The waiting of ranks for each other is left out.

usage: scaling_estimate.py COUNTS.csv [--elements S] [--update S] [--slaves S]
       [--replicated S] [--steps N] [--p2p US] [--collective US]
(defaults: the paper case on 2 ranks of the AMD EPYC Zen 5 host, f069d35,
doc/notes/performance_targets.md)
"""
import argparse
import csv
import math


def read_counts(path):
    with open(path) as f:
        lines = [l for l in f if l.startswith("ranks,") or (l[:1].isdigit() and l.count(",") >= 8)]
    return list(csv.DictReader(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("counts", help="output of build/partition_counts")
    ap.add_argument("--elements", type=float, default=786.5 + 890.2,
                    help="element loop, rank-seconds on 2 ranks (sum over the ranks)")
    ap.add_argument("--update", type=float, default=156.0 + 175.5,
                    help="nodal update, rank-seconds on 2 ranks")
    ap.add_argument("--slaves", type=float, default=48.3 + 54.5,
                    help="contact's computed slaves, rank-seconds on 2 ranks")
    ap.add_argument("--replicated", type=float, default=72.0,
                    help="contact's replicated part (positions, exchange, forces, search), "
                         "seconds of one rank")
    ap.add_argument("--output", type=float, default=20.0, help="output, seconds of one rank")
    ap.add_argument("--steps", type=int, default=217577)
    ap.add_argument("--p2p", type=float, default=2.0,
                    help="one point-to-point message [us] (mpi_exchange: exchange of 1 kB)")
    ap.add_argument("--collective", type=float, default=2.0,
                    help="one round of a collective [us] (mpi_exchange: all-reduce on 2 ranks)")
    ap.add_argument("--per-kb", type=float, default=0.19,
                    help="a message's time per kB [us] (mpi_exchange: 128 kB / 128)")
    ap.add_argument("--collectives", type=int, default=7, help="collectives per step")
    args = ap.parse_args()

    rows = read_counts(args.counts)
    base = None
    print("ranks  elements  update  slaves  replicated  messages  output  total [s]  speed-up  efficiency")
    for r in rows:
        n = int(r["ranks"])
        owned_mean = (float(r["owned_nodes_min"]) + float(r["owned_nodes_max"])) / 2
        node_imbalance = float(r["owned_nodes_max"]) / owned_mean
        el = args.elements / n * float(r.get("work_max_over_mean") or 1)
        up = args.update / n * node_imbalance
        sl = args.slaves / n
        ghost_kb = float(r["ghosts_per_owned_max"]) * owned_mean * 24 / 1024
        lat = args.steps * 1e-6 * (3 * 2 * int(r["neighbours_max"]) * args.p2p
                                   + 3 * ghost_kb * args.per_kb
                                   + args.collectives * math.ceil(math.log2(n)) * args.collective)
        total = el + up + sl + args.replicated + lat + args.output
        if base is None:
            base = (n, total)
        speedup = base[1] / total
        eff = speedup * base[0] / n
        print(f"{n:5d}  {el:8.1f}  {up:6.1f}  {sl:6.1f}  {args.replicated:10.1f}  {lat:8.1f}  "
              f"{args.output:6.1f}  {total:9.1f}  {speedup:8.2f}  {eff:10.2f}")


if __name__ == "__main__":
    main()
