"""``python3 -m quadsect_check FILE|-``: one JSON verdict line per answer
line, then ``N verified, N partial, N rejected``; exit status 0 iff
nothing is rejected (2 when the input cannot be read)."""

import json
import sys

from . import check_line


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1 or args[0] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 0 if args and args[0] in ("-h", "--help") else 2
    try:
        src = sys.stdin if args[0] == "-" else open(args[0], encoding="utf-8")
    except OSError as e:
        print(f"quadsect_check: cannot open {args[0]}: {e}", file=sys.stderr)
        return 2
    counts = {"verified": 0, "partial": 0, "rejected": 0}
    with src:
        for line in src:
            if not line.strip():
                continue
            r = check_line(line)
            counts[r["status"]] += 1
            print(json.dumps(r, ensure_ascii=False))
    print(f"{counts['verified']} verified, {counts['partial']} partial, {counts['rejected']} rejected")
    return 1 if counts["rejected"] else 0


if __name__ == "__main__":
    sys.exit(main())
