"""Helpers shared by the tests: the repository's protocol examples and a scripted socket."""

import re
from pathlib import Path
from typing import Dict, Iterable, List

REPO_ROOT = Path(__file__).resolve().parents[2]
PROTOCOL_MD = REPO_ROOT / "docs" / "protocol.md"

_EXAMPLE = re.compile(r"<!-- example: ([\w-]+) -->\s*```hex\n(.*?)```", re.S)


def protocol_examples() -> Dict[str, bytes]:
    """Every ``<!-- example: NAME -->`` hex block of docs/protocol.md, as bytes (text after ``#`` on
    a line is commentary, spaces only group the digits)."""
    examples: Dict[str, bytes] = {}
    for name, block in _EXAMPLE.findall(PROTOCOL_MD.read_text(encoding="utf-8")):
        digits = "".join(line.split("#", 1)[0] for line in block.splitlines())
        examples[name] = bytes.fromhex("".join(digits.split()))
    return examples


class ScriptedSocket:
    """A socket double: ``recv_into`` hands out the given chunks one by one (never joining two),
    then end of stream; ``sendall`` records each message."""

    def __init__(self, chunks: Iterable[bytes] = ()) -> None:
        self.chunks: List[bytes] = [bytes(c) for c in chunks if c]
        self.sent: List[bytes] = []
        self.closed = False

    def feed(self, *chunks: bytes) -> None:
        self.chunks.extend(bytes(c) for c in chunks if c)

    def recv_into(self, view: memoryview) -> int:
        if not self.chunks:
            return 0
        chunk = self.chunks.pop(0)
        n = min(len(chunk), len(view))
        view[:n] = chunk[:n]
        if n < len(chunk):
            self.chunks.insert(0, chunk[n:])
        return n

    def sendall(self, data: bytes) -> None:
        self.sent.append(bytes(data))

    def shutdown(self, how: int) -> None:
        pass

    def close(self) -> None:
        self.closed = True
