#!/usr/bin/env python3
"""What the bricks' shadow exchange costs a rank per frame and light, to 1,024 ranks: the
all-gather of every rank's light-space totals against the scan along the light
(vtkDeepShadowBrickExchange), as a markdown table for Documentation/ParaView.md.

    scripts/exchange-model.py [--map 512] [--channels 1] [--mb-per-s 750] [--latency-ms 0.01]

Bytes and messages follow the scan's schedule position by position (Hillis and Steele: in
round r the brick at position p >= 2^r receives one map from p - 2^r), as
Core/Shadows/Bricks.cxx runs it; both ways also gather the bricks' boxes (40 bytes from each
other rank). Messages count an all-gather as ranks - 1 received pieces, as
ShadowExchangeMessages does. They match what ParaView.ranks measures at 2, 4 and 8 ranks. Time is a model:
bytes over a bandwidth plus a latency per message round; the defaults are this machine's
two-rank measurement (1 MiB scanned in 1.4 ms, shared memory) and an assumed 10 us latency.
"""
import argparse

BOX_BYTES = 40  # a brick's box, the map's shape and its lights' signature (10 floats)


def scan_receives(ranks):
    """Maps received by each position of the light's order."""
    received = [0] * ranks
    stride = 1
    while stride < ranks:
        for position in range(stride, ranks):
            received[position] += 1
        stride *= 2
    return received


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", type=int, default=512)
    parser.add_argument("--channels", type=int, default=1)
    parser.add_argument("--mb-per-s", type=float, default=750.0)
    parser.add_argument("--latency-ms", type=float, default=0.01)
    args = parser.parse_args()
    map_bytes = args.map * args.map * 4 * args.channels
    per_ms = args.mb_per_s * 1e6 / 1e3
    print("| ranks | gathered: MiB a rank receives | messages | ms (model) | scanned: MiB, most | "
          "MiB, mean | messages | ms (model) |")
    print("|---|---|---|---|---|---|---|---|")
    ranks = 1
    while ranks <= 1024:
        boxes = (ranks - 1) * BOX_BYTES
        rounds = max(1, (ranks - 1).bit_length()) if ranks > 1 else 0
        gather = (ranks - 1) * map_bytes + boxes
        received = scan_receives(ranks)
        most = max(received) * map_bytes + boxes
        mean = sum(received) / ranks * map_bytes + boxes
        # The gather's messages as MPI's ring all-gather moves them; its latency as recursive
        # doubling's rounds (the cheaper of the two for the model).
        gather_ms = gather / per_ms + 2 * rounds * args.latency_ms
        scan_ms = most / per_ms + (rounds + rounds) * args.latency_ms
        mib = 1024.0 * 1024.0
        print(f"| {ranks} | {gather / mib:.2f} | {2 * (ranks - 1)} | {gather_ms:.1f} | {most / mib:.2f} | "
              f"{mean / mib:.2f} | {max(received) + ranks - 1 if ranks > 1 else 0} | {scan_ms:.1f} |")
        ranks *= 2


if __name__ == "__main__":
    main()
