#!/usr/bin/python3
"""Every external program that Tumble's tests, scripts and packaging run is installed by
scripts/setup.sh, or comes with every Debian 12 machine (issue 26).

A bare Debian 12 root (debootstrap minbase) has the Essential packages and apt, with their
dependencies, and nothing else. The developer machines have far more, so a program the set-up
forgets stays hidden until a new user runs the README's commands. This check finds the programs
from the sources themselves, so that a new use is checked without anyone listing it:

  - shell scripts (scripts/, .ci/, tests/): the first word of every simple command;
  - C++ sources (tests/, app/, bench/): string literals that are shell commands (their first word
    is an installed program followed by an option or argument, or a pipe's next command);
  - CMake files: the words after COMMAND;
  - CPack's DEB generator (cmake's own CPackDeb.cmake): every program it finds with find_program;
  - Python scripts (tests/, scripts/, and Python run from shell here-documents): their imports.

Each program is resolved on this machine (PATH, alternatives followed) to the Debian package that
owns it (dpkg -S), and that package must be in the closure, over Depends and Pre-Depends, of the
packages of the set-up that runs it: Essential + apt + `scripts/setup.sh --list demo` for
scripts/demo.sh, and the same + `--list test` for everything else (scripts/test.sh installs
both). A program that is not installed here fails too: the set-up would not have installed it.

usage: external_programs.py SOURCE_DIR      (prints one line per program; exit 1 on a gap)
"""
import glob
import os
import re
import shutil
import subprocess
import sys

SHELL_WORDS = {
    # builtins of bash (and dash): not programs
    "echo", "printf", "read", "cd", "pwd", "export", "local", "declare", "typeset", "readonly",
    "set", "unset", "shift", "return", "exit", "trap", "wait", "eval", "source", ".", "test",
    "true", "false", "break", "continue", "type", "hash", "kill", "jobs", "umask", "let",
    "getopts", "mapfile", "readarray", "builtin", "alias", "ulimit", "shopt", "pushd", "popd",
    "disown", "bg", "fg", ":", "[",
}
# Words that run the word after them (with their own options skipped) or open a compound command.
PREFIXES = {"nice", "nohup", "sudo", "env", "timeout", "xargs", "exec", "time", "command",
            "stdbuf", "chroot", "!"}
BUILTIN_PREFIXES = {"exec", "time", "command", "!"}
STARTERS = {"then", "do", "else", "elif", "if", "while", "until", "{", "!"}
# Words a scan sees in command position that are not programs for the set-up to install.
NOT_PROGRAMS = {
    "sudo": "setup.sh runs it only for a user who is not root, who has it by definition",
    "git": "scripts/update-references.sh works on a clone of the repository, made with git",
    "tumble": "the program under test, built by the project",
}
# Demo-only sources: what scripts/demo.sh runs (the rest of the tree needs the test set-up).
DEMO_SOURCES = {"scripts/demo.sh", "scripts/setup.sh"}
# The directories of a Debian machine's PATH: a program elsewhere (/usr/local, ~/.pyenv) is not
# one the set-up installed.
SYSTEM_PATH = "/usr/sbin:/usr/bin:/sbin:/bin"


def which(name):
    return shutil.which(name, path=SYSTEM_PATH) if not name.startswith("/") else (
        name if os.access(name, os.X_OK) else None)


class ShellLexer:
    """Enough of the shell's grammar to find command words: words (quotes kept as written),
    operators, redirections (whose targets are files), here-documents, and command
    substitutions, whose insides are lexed again."""

    REDIRECTS = ["<<<", "&>>", "2>&", "1>&", "2>>", ">>", "&>", ">&", "<&", "2>", ">|", "<", ">"]
    OPS = ["&&", "||", ";;", "|&", "<<-", "<<"] + REDIRECTS + [";", "|", "&", "(", ")"]

    def __init__(self, text):
        self.text, self.i = text, 0
        self.substitutions = []  # texts inside $( ) and backquotes
        self.bodies = []  # (the command reading a here-document, its body)

    def skip_blanks(self):
        while self.i < len(self.text) and self.text[self.i] in " \t":
            self.i += 1

    def tokens(self):
        out, pending = [], []
        t, n = self.text, len(self.text)
        while self.i < n:
            c = t[self.i]
            if t.startswith("\\\n", self.i):
                self.i += 2
            elif c in " \t":
                self.i += 1
            elif c == "#" and (self.i == 0 or t[self.i - 1] in " \t\n;"):
                while self.i < n and t[self.i] != "\n":
                    self.i += 1
            elif c == "\n":
                self.i += 1
                out.append(("op", "\n"))
                for delim in pending:  # here-document bodies start on the next line
                    start = self.i
                    while self.i < n:
                        end = t.find("\n", self.i)
                        end = n if end < 0 else end
                        line = t[self.i:end]
                        self.i = end + 1
                        if line.strip() == delim:
                            break
                    self.bodies.append((self.current_command(out), t[start:self.i]))
                pending = []
            else:
                op = next((o for o in self.OPS if t.startswith(o, self.i)), None)
                if op is None:
                    out.append(("word", self.word()))
                    continue
                self.i += len(op)
                if op in ("<<", "<<-"):
                    self.skip_blanks()
                    pending.append(self.word().strip("'\""))
                elif op in self.REDIRECTS:  # its target is a file, not a command
                    self.skip_blanks()
                    if self.i < n and t[self.i] not in "\n;|&":
                        self.word()
                else:
                    out.append(("op", op))
        return out

    @staticmethod
    def current_command(out):
        words = []
        for kind, v in reversed(out[:-1]):
            if kind == "op" and v in ("\n", ";", "&&", "||", "|"):
                break
            if kind == "word":
                words.append(v)
        return words[-1] if words else ""

    def word(self):
        t, n, start = self.text, len(self.text), self.i
        while self.i < n:
            c = t[self.i]
            if c in " \t\n;&|<>)" or c == "(" and not (self.i > start and t[self.i - 1] == "="):
                break
            if c == "\\":
                self.i += 2
            elif c == "'":
                self.i = t.find("'", self.i + 1) + 1 or n
            elif c == '"':
                self.double_quoted()
            elif t.startswith("$((", self.i):
                self.i = t.find("))", self.i) + 2 or n
            elif t.startswith("$(", self.i):
                self.substitution()
            elif t.startswith("${", self.i):
                self.i = self.closing_brace(self.i + 2)
            elif c == "`":
                end = t.find("`", self.i + 1)
                self.substitutions.append(t[self.i + 1:end])
                self.i = end + 1
            elif c == "(":  # an array: name=( ... ), quotes and all
                self.i = self.closing_paren(self.i + 1)
            else:
                self.i += 1
        return t[start:self.i]

    def double_quoted(self):
        t, n = self.text, len(self.text)
        self.i += 1
        while self.i < n and t[self.i] != '"':
            if t[self.i] == "\\":
                self.i += 2
            elif t.startswith("$((", self.i):
                self.i = t.find("))", self.i) + 2 or n
            elif t.startswith("$(", self.i):
                self.substitution()
            elif t.startswith("${", self.i):
                self.i = self.closing_brace(self.i + 2)
            else:
                self.i += 1
        self.i += 1

    def closing_brace(self, i):
        """The index after the '}' that closes a '${' just before i."""
        depth = 1
        while i < len(self.text) and depth:
            depth += {"{": 1, "}": -1}.get(self.text[i], 0)
            i += 1
        return i

    def closing_paren(self, i):
        """The index after the ')' that closes a '(' just before i (quotes and nesting kept)."""
        t, n, depth = self.text, len(self.text), 1
        while i < n and depth:
            c = t[i]
            if c == "\\":
                i += 1
            elif c == "#" and t[i - 1] in " \t\n":  # a comment, parentheses and all
                i = t.find("\n", i)
            elif c == "'":
                i = t.find("'", i + 1)
            elif c == '"':
                save = self.i
                self.i = i
                self.double_quoted()
                i, self.i = self.i - 1, save
            elif c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
            i += 1
        return i

    def substitution(self):
        start = self.i + 2
        self.i = self.closing_paren(start)
        self.substitutions.append(self.text[start:self.i - 1])


def command_words(text):
    """The first word of every simple command in a shell text (with $(...) inside), and the
    here-document bodies with the command that reads them."""
    lexer = ShellLexer(text)
    tokens = lexer.tokens()
    words, at_start, skip_to, i = [], True, None, 0
    while i < len(tokens):
        kind, v = tokens[i]
        i += 1
        if skip_to:
            if kind == "word" and v == skip_to or kind == "op" and v == skip_to:
                skip_to = None
                at_start = True
            continue
        if kind == "op":
            at_start = v in ("\n", ";", "&&", "||", "|", "|&", "&", "(", ";;")
            if v == ")" and tokens[i - 2] == ("op", "("):  # name() { ... }
                at_start = True
            continue
        if not at_start:
            continue
        if i < len(tokens) and tokens[i] == ("op", ")"):  # a case pattern: "demo) ..."
            continue
        if re.match(r"^[A-Za-z_][A-Za-z0-9_]*(\[[^]]*\])?\+?=", v):  # an assignment
            continue
        if v in STARTERS:
            continue
        if v == "for" or v == "select":
            skip_to = "do"
            continue
        if v == "case":
            skip_to = "in"
            continue
        if v in ("[[", "(("):
            skip_to = "]]" if v == "[[" else "))"
            continue
        if v in ("fi", "done", "esac", "}", "in", "function"):
            at_start = v != "function" and False
            continue
        if v in PREFIXES:
            words.append(v)
            while i < len(tokens) and tokens[i][0] == "word" and re.match(r"^(-\S*|\d\S*)$", tokens[i][1]):
                i += 1
            continue
        words.append(v)
        at_start = False
    # case patterns: "pattern)" then a command
    for sub in lexer.substitutions:
        inner, bodies = command_words(sub)
        words += inner
        lexer.bodies += bodies
    return words, lexer.bodies


def shell_programs(path):
    """Programs run by one shell script, and the Python here-documents it feeds python3."""
    text = open(path, encoding="utf-8").read()
    functions = set(re.findall(r"^\s*(?:function\s+)?([A-Za-z_][A-Za-z0-9_-]*)\s*\(\)\s*\{?", text, re.M))
    words, bodies = command_words(text)
    programs = {w for w in words if w not in SHELL_WORDS | BUILTIN_PREFIXES and w not in functions
                and re.match(r"^[A-Za-z0-9_./+-]+$", w) and not w.startswith("-")}
    return programs, [b for cmd, b in bodies if re.search(r"python3?$", cmd)]


LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')


def cpp_programs(path):
    """Programs in C++ string literals that are shell commands: the literal's first word is an
    installed program followed by an option, a quote, a variable or a path (or the literal goes
    on a pipe), and the commands after its pipes and substitutions."""
    text = open(path, encoding="utf-8", errors="replace").read()
    text = re.sub(r"'(?:[^'\\\n]|\\.)'", "''", text)  # character literals ('"')
    text = re.sub(r"//[^\n]*", "", text)
    if not re.search(r"\b(popen|system|run_shell|execl|execv|execvp)\s*\(", text):
        return set()  # runs no command
    programs = set()
    for lit in LITERAL.findall(text):
        first = re.match(r"\s*([A-Za-z0-9_./+-]+)\s+[-'\"$/]", lit)
        piped = re.match(r"\s*(\||&&)", lit)
        if not (first and which(first.group(1))) and not piped:
            continue
        if first and which(first.group(1)):
            programs.add(first.group(1))
        for w in re.findall(r"(?:\||\$\(|&&)\s*([A-Za-z0-9_./+-]+)", lit):
            if which(w) and w not in SHELL_WORDS:
                programs.add(w)
    return programs


def cmake_programs(path):
    programs = set()
    for w in re.findall(r"\bCOMMAND\s+(\S+)", open(path, encoding="utf-8").read()):
        if "${" not in w and "$<" not in w:  # a target or a variable: built here, or CMake's own
            programs.add(w)
    return programs


def cpack_programs():
    """What CPack's DEB generator looks for (find_program), from cmake's own module."""
    modules = glob.glob("/usr/share/cmake-*/Modules/Internal/CPack/CPackDeb.cmake")
    if not modules:
        sys.exit("FAIL: cmake's CPackDeb.cmake not found: cannot tell what CPack runs")
    text = open(modules[0], encoding="utf-8").read()
    names = re.findall(r"find_program\(\s*\w+\s+(?:NAMES\s+)?([A-Za-z0-9_.+-]+)", text)
    return set(names), modules[0]


def python_imports(text):
    mods = set()
    for m in re.finditer(r"^\s*(?:import\s+([\w.]+(?:\s*,\s*[\w.]+)*)|from\s+([\w.]+)\s+import)",
                         text, re.M):
        for name in (m.group(1) or m.group(2)).split(","):
            mods.add(name.strip().split(".")[0])
    return mods


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True)


def candidates(path):
    """The names dpkg may record a file under: following symbolic links and alternatives, and
    under /bin and /sbin for files usrmerge reaches through /usr (and back)."""
    out = []
    for p in (os.path.realpath(path), path):
        for q in (p, re.sub(r"^/usr/(s?bin)/", r"/\1/", p), re.sub(r"^/(s?bin)/", r"/usr/\1/", p)):
            if q not in out:
                out.append(q)
    return out


def owners(paths):
    """The Debian package owning each of `paths` (None when none does), with one dpkg call."""
    names = sorted({c for p in paths for c in candidates(p)})
    r = run(["dpkg", "-S"] + names)
    owned = {}
    for line in r.stdout.splitlines():
        if line.startswith("diversion by") or ": " not in line:
            continue
        packages, path = line.split(": ", 1)
        owned.setdefault(path, packages.split(",")[0].split(":")[0].strip())
    return {p: next((owned[c] for c in candidates(p) if c in owned), None) for p in paths}


def installed_packages():
    r = run(["dpkg-query", "-W", "-f", "${Package}\t${Status}\t${Essential}\t${Provides}\t${Pre-Depends}\t${Depends}\n"])
    table = {}
    for line in r.stdout.splitlines():
        name, status, essential, provides, pre, deps = (line.split("\t") + [""] * 6)[:6]
        if "install ok installed" not in status:
            continue
        table[name] = (essential == "yes", provides, pre + ", " + deps)
    return table


def closure(roots, table):
    """Installed packages reached from `roots` over Depends and Pre-Depends (an alternative
    'a | b' by whichever is installed; virtual names through Provides)."""
    provided = {}
    for name, (_, provides, _) in table.items():
        for p in provides.split(","):
            p = p.strip().split(" ")[0]
            if p:
                provided.setdefault(p, []).append(name)
    seen, todo = set(), [r for r in roots if r in table]
    while todo:
        p = todo.pop()
        if p in seen:
            continue
        seen.add(p)
        for clause in table[p][2].split(","):
            for alt in clause.split("|"):
                name = alt.strip().split(" ")[0].split(":")[0]
                if not name:
                    continue
                targets = [name] if name in table else provided.get(name, [])
                if targets:
                    todo.extend(targets)
                    break
    return seen


def setup_list(source, group):
    r = run(["bash", os.path.join(source, "scripts/setup.sh"), "--list", group])
    if r.returncode != 0 or not r.stdout.split():
        sys.exit("FAIL: scripts/setup.sh --list %s printed no packages: %s" % (group, r.stderr))
    return r.stdout.split()


def tree_files():
    """The repository's files, relative paths, without build and output folders or .git."""
    out = []
    for top, dirs, files in os.walk("."):
        dirs[:] = [d for d in dirs if d != ".git" and not d.startswith(("build", "out"))]
        out += [os.path.relpath(os.path.join(top, f)) for f in files]
    return sorted(out)


def main():
    source = os.path.abspath(sys.argv[1])
    os.chdir(source)
    uses = {}  # program -> set of files that run it

    def use(program, where):
        uses.setdefault(program, set()).add(where)

    pythons = []
    tree = tree_files()
    shells = [f for f in tree if f.startswith("scripts/") or f.startswith("tests/") and f.endswith(".sh")
              or f == ".ci/run"]
    shells = [f for f in shells if f.endswith(".sh") or f == ".ci/run" or f.startswith("scripts/slurm/")
              or open(f, "rb").read(64).startswith(b"#!/bin/bash")]
    for f in sorted(set(shells)):
        programs, bodies = shell_programs(f)
        for p in programs:
            use(p, f)
        pythons += [(f, b) for b in bodies]
    for f in [f for f in tree if f.endswith(".py") and f.startswith(("tests/", "scripts/"))]:
        pythons.append((f, open(f, encoding="utf-8").read()))
        use("/usr/bin/python3", f)
    for f in [f for f in tree if f.startswith(("tests/", "app/", "bench/")) and f.endswith((".cpp", ".h"))]:
        for p in cpp_programs(f):
            use(p, f)
    for f in [f for f in tree if f.endswith(("CMakeLists.txt", ".cmake"))]:
        for p in cmake_programs(f):
            use(p, f)
    cpack, module = cpack_programs()
    for p in cpack:
        use(p, "CPack DEB (%s)" % module)

    table = installed_packages()
    base = [p for p, (essential, _, _) in table.items() if essential] + ["apt"]
    demo = closure(base + setup_list(source, "demo"), table)
    full = closure(base + setup_list(source, "demo") + setup_list(source, "test"), table)

    gaps, found = [], []  # found: (name, path, where)
    local_names = {os.path.basename(f) for f in tree}
    for name in sorted(uses):
        where = uses[name]
        if name in NOT_PROGRAMS or name.startswith(("build/", "scripts/", "$")):
            continue
        if name in local_names and not which(name):
            continue  # a script or file of the repository, run by path
        path = which(name)
        if not path:
            gaps.append("%s: run by %s, but not installed on this machine" % (name, ", ".join(sorted(where))))
            continue
        found.append((name, path, where))

    locals_py = {os.path.splitext(os.path.basename(f))[0] for f in tree if f.endswith(".py")}
    # The repository's own packages (app/python/tumble: the module the build makes) are not Debian's.
    locals_py |= {os.path.basename(os.path.dirname(f)) for f in tree if f.endswith("/__init__.py")}
    for module in sorted(set().union(*(python_imports(t) for _, t in pythons)) - locals_py):
        where = {f for f, t in pythons if module in python_imports(t)}
        r = run(["/usr/bin/python3", "-c", "import %s as m; print(getattr(m, '__file__', '') or '')" % module])
        if r.returncode != 0:
            gaps.append("python3 module %s: imported by %s, but /usr/bin/python3 cannot import it"
                        % (module, ", ".join(sorted(where))))
        elif r.stdout.strip():  # else built into the interpreter
            found.append(("py:" + module, r.stdout.strip(), where))

    packages = owners([path for _, path, _ in found])
    for name, path, where in found:
        pkg = packages[path]
        demo_only = where <= DEMO_SOURCES
        if pkg is None:
            gaps.append("%s (%s): no Debian package owns it" % (name, path))
        elif pkg not in (demo if demo_only else full):
            gaps.append("%s: from package %s, which neither Essential nor `setup.sh --list %s` "
                        "brings (run by %s)" % (name, pkg, "demo" if demo_only else "test",
                                                ", ".join(sorted(where))))
        print("%-18s %-28s %s" % (name, pkg, ", ".join(sorted(where))))
    checked = len(found)
    print("%d programs and modules checked" % checked)
    if checked < 15:
        gaps.append("only %d programs found: the scan is broken and would prove little" % checked)
    for g in gaps:
        print("FAIL:", g)
    sys.exit(1 if gaps else 0)


if __name__ == "__main__":
    main()
