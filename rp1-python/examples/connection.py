"""The --host and --port options of the examples, connecting with them, and ending quietly."""

import argparse
import sys
from typing import Callable, List, Optional

import rp1client as rp


def argument_parser(doc: str) -> argparse.ArgumentParser:
    """A parser described by the first paragraph of ``doc``, with --host and --port."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--host", default=None, help="simulator host (default: rossum.ini, else 127.0.0.1)")
    parser.add_argument("--port", type=int, default=None, help="simulator port (default: rossum.ini, else 7758)")
    return parser


def connect(args: argparse.Namespace, program: str) -> Optional[rp.Client]:
    """A client connected to the simulator the options name, or None after saying why not, in one line."""
    try:
        return rp.Client(args.host, args.port).connect(timeout=10.0)
    except (OSError, rp.ProtocolError, rp.SettingsError) as e:
        print(f"{program}: {e}", file=sys.stderr)
        return None


PLACEMENT_REFUSED = ("refused: the plan has no placement of that name, or a wall or another robot is in "
                     "the way (the simulator's log says which)")


def run_main(main: Callable[[Optional[List[str]]], int]) -> int:
    """``main()``'s exit status; Ctrl-C ends it with status 130 and one line instead of a traceback."""
    try:
        return main(None)
    except KeyboardInterrupt:
        print("stopped (Ctrl-C)", file=sys.stderr)
        return 130
