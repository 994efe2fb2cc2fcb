"""A client's ``rossum.ini``: where the server is, as the Java library reads it (docs/properties.md).

The file is a Java properties file (``key=value``, ``key: value`` or ``key value``; ``#`` and ``!``
start comment lines). Only the first word of a value counts, so a comment after a value is harmless.
``hostName`` and ``port`` say where to connect. The log keys are read and checked like the Java
library's, so one file serves both; what this library logs goes to Python's :mod:`logging` (logger
``rp1client``), which the program configures.
"""

import os
import re
from dataclasses import dataclass, replace
from typing import Dict, Optional

from .errors import SettingsError

FILE_NAME = "rossum.ini"
MIN_PORT = 1
MAX_PORT = 65535

_SEPARATOR = re.compile(r"\s*[=:]\s*|\s+")


@dataclass(frozen=True)
class ClientSettings:
    """The client keys of ``rossum.ini`` with the Java library's packaged defaults."""

    host_name: str = "127.0.0.1"
    port: int = 7758
    log_file_name: str = "rossum.log"
    log_to_file: bool = False
    log_to_system_out: bool = False
    log_verbose: bool = False

    @classmethod
    def load(cls, path: str, base: "Optional[ClientSettings]" = None) -> "ClientSettings":
        """The settings of ``base`` (the defaults if None) overridden by the keys of file ``path``.

        Raises:
            SettingsError: naming the key, the value and the file, if a value cannot be used.
            OSError: if the file cannot be read.
        """
        with open(path, encoding="latin-1") as f:
            values = _parse(f.read())
        return _apply(base or cls(), values, path)

    @classmethod
    def from_working_directory(cls) -> "ClientSettings":
        """``./rossum.ini`` if there is one, else the defaults."""
        return cls.load(FILE_NAME) if os.path.isfile(FILE_NAME) else cls()


def _parse(text: str) -> Dict[str, str]:
    """Key/value lines of a properties file (continuation lines and escapes are not supported)."""
    values: Dict[str, str] = {}
    for raw in text.splitlines():
        line = raw.strip()
        if not line or line[0] in "#!":
            continue
        parts = _SEPARATOR.split(line, maxsplit=1)
        values[parts[0]] = parts[1] if len(parts) > 1 else ""
    return values


def _first_word(value: Optional[str]) -> Optional[str]:
    words = (value or "").split()
    return words[0] if words else None


def _apply(base: ClientSettings, values: Dict[str, str], source: str) -> ClientSettings:
    changes: Dict[str, object] = {}
    host = _first_word(values.get("hostName"))
    if "hostName" in values and host is None:
        raise SettingsError(f"Missing mandatory specification for hostName ({source})")
    if host is not None:
        changes["host_name"] = host
    port = _first_word(values.get("port"))
    if "port" in values:
        changes["port"] = _port(port, source)
    log_file = _first_word(values.get("logFileName"))
    if log_file is not None:
        changes["log_file_name"] = log_file
    for key, attr in (("logToFile", "log_to_file"), ("logToSystemOut", "log_to_system_out"),
                      ("logVerbose", "log_verbose")):
        if key in values:
            changes[attr] = _boolean(key, _first_word(values[key]), source)
    settings = replace(base, **changes)  # type: ignore[arg-type]
    if settings.log_to_file and log_file is None and "logFileName" in values:
        raise SettingsError(f"The logToFile option was requested, but logFileName is missing ({source})")
    return settings


def _port(value: Optional[str], source: str) -> int:
    if value is None:
        raise SettingsError(f"Missing mandatory specification for port ({source})")
    try:
        port = int(value)
    except ValueError:
        raise SettingsError(f'Bad number format for integer port specification: "{value}" ({source})') from None
    if not MIN_PORT <= port <= MAX_PORT:
        raise SettingsError(f"Integer port number {port} not in valid range [{MIN_PORT},{MAX_PORT}] ({source})")
    return port


def _boolean(key: str, value: Optional[str], source: str) -> bool:
    if value is None:
        return False
    if value.lower() in ("true", "false"):
        return value.lower() == "true"
    raise SettingsError(f'Invalid specification where true/false expected for {key}: "{value}" ({source})')
