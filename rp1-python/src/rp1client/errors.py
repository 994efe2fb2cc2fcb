"""The exceptions of rp1client."""


class ProtocolError(Exception):
    """The server broke the RP1 wire protocol, or a byte string is not a well-formed message.

    Raised for a wrong version, client id or key, an unknown transaction, request, event, part or
    plan-object code, a count outside its limit, text that is not modified UTF-8, or input that ends
    in the middle of a message. ``str(error)`` reads ``FIELD: PROBLEM``, as the Java library's
    ``RsProtocolException`` does.

    Attributes:
        field: the name of the field being read when the problem was found.
        problem: what was wrong with it.
        truncated: true when the input simply ended inside the message (more bytes may complete it).
    """

    def __init__(self, field: str, problem: str, truncated: bool = False) -> None:
        super().__init__(f"{field}: {problem}")
        self.field = field
        self.problem = problem
        self.truncated = truncated


class SettingsError(ValueError):
    """A ``rossum.ini`` value cannot be used; the message names the key, the value and the file."""
