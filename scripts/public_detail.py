"""Finds `detail::` in what an installed header makes public (doc/architecture.md, "Private is
private"): a declaration at namespace scope or among the public members of a class, outside
`namespace detail`, whose signature, type or base names something in a `detail` namespace.
Function bodies, private and protected members, friends and constructor initializers are
implementation and may use `detail`. Used by check-layers.py.
"""

import re

# What can hide a brace or a word: comments, string and character literals, preprocessor lines.
HIDDEN = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|^[ \t]*#[^\n]*', re.S | re.M)
ACCESS = re.compile(r"^(public|private|protected)$")
# The end of a constructor's parameter list and the start of its member initializers.
INITIALIZERS = re.compile(r"\)\s*(?:noexcept\s*)?:(?!:)")


def blanked(text):
    """`text` with comments, literals and preprocessor lines replaced by spaces (lines kept)."""
    return HIDDEN.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


class _Scope:
    def __init__(self, kind, name="", access="public"):
        self.kind, self.name, self.access = kind, name, access


def _opened(head):
    """The scope a `{` after `head` opens."""
    if re.search(r"\bnamespace\b", head):
        match = re.search(r"\bnamespace\s+([\w:]+)", head)
        return _Scope("namespace", match.group(1) if match else "")
    if re.search(r"\benum\b", head):
        return _Scope("body")
    match = re.search(r"\b(class|struct|union)\s+\w+[^()]*$", head)
    if match:
        return _Scope("class", access="private" if match.group(1) == "class" else "public")
    return _Scope("body")


def _hidden_from_users(stack):
    """Whether a declaration here is out of a user's sight: in a detail namespace, a function
    body, or a class region that is not public."""
    for scope in stack:
        if scope.kind == "body" or (scope.kind == "namespace" and scope.name.split("::")[-1] == "detail"):
            return True
        if scope.kind == "class" and scope.access != "public":
            return True
    return False


def public_detail_uses(text):
    """(line, declaration) of every public declaration of `text` (a header) that names detail::."""
    code = blanked(text)
    stack, start, found = [], 0, []

    def check(end, opens_body):
        head = code[start:end]
        if _hidden_from_users(stack) or re.search(r"\bfriend\b", head):
            return
        if opens_body:
            initializers = INITIALIZERS.search(head)
            head = head[: initializers.start() + 1] if initializers else head
        at = head.find("detail::")
        if at >= 0:
            found.append((code.count("\n", 0, start + at) + 1, " ".join(head.split())))

    for i, c in enumerate(code):
        if c == "{":
            scope = (
                _opened(code[start:i]) if not _hidden_from_users(stack) or stack[-1].kind != "body" else _Scope("body")
            )
            if scope.kind == "body" or scope.kind == "class":
                check(i, scope.kind == "body")
            stack.append(scope)
            start = i + 1
        elif c == "}":
            if stack:
                stack.pop()
            start = i + 1
        elif c == ";":
            if not stack or stack[-1].kind != "body":
                check(i, False)
            start = i + 1
        elif c == ":" and stack and stack[-1].kind == "class" and code[i + 1 : i + 2] != ":" and code[i - 1] != ":":
            word = code[start:i].strip()
            if ACCESS.match(word):
                stack[-1].access = word
                start = i + 1
    return found
