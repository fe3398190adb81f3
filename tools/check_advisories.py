#!/usr/bin/env python3
"""Check the crate versions locked in Cargo.lock against a RustSec advisory database, offline.

    python3 tools/check_advisories.py --db PATH/TO/advisory-db [Cargo.lock ...]
    python3 tools/check_advisories.py --db PATH/TO/advisory-db --self-test

The database is a copy of the RustSec advisory database (github.com/rustsec/advisory-db):
`crates/<name>/RUSTSEC-*.md`, each opening with TOML front matter in a ```toml block whose
`[advisory]` table has the id, the date, `informational` and `withdrawn`, and whose `[versions]`
table lists `patched` and `unaffected` semver requirements. A locked version is affected when
it matches none of them (as `cargo audit` decides). Only crates from a registry are checked:
the path and git dependencies have no advisories.

Policy:
* a vulnerability (no `informational` kind) or an `informational = "unsound"` advisory that
  affects a locked version fails the check (exit 1);
* `unmaintained` and `notice` advisories (and any other informational kind) are listed as
  warnings: they say nothing is wrong with the code today, and there may be no replacement;
* withdrawn advisories are ignored;
* an advisory listed in the allow file (tools/advisories_allowed.txt: one `RUSTSEC-YYYY-NNNN
  reason` a line) is reported with its reason but does not fail: accepting an advisory takes a
  written reason in the repository.

The database's age (its SNAPSHOT.txt date if it has one, else its newest advisory) is printed:
an advisory published after the copy was made is not seen. Exit 2 when the database or a lock
file is missing or unreadable. Python standard library only (tomllib: Python 3.11).
"""
import argparse
import datetime
import os
import re
import sys
import tempfile
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_ALLOW = os.path.join(HERE, "advisories_allowed.txt")
FAILING = {None, "unsound"}


# --- semver requirements (the `semver` crate's comparators, as cargo-audit reads them) -----------

def parse_version(text):
    """(major, minor, patch, pre) of `1.2.3-alpha.1+build`; pre is a tuple of identifiers."""
    core = text.strip().split("+", 1)[0]
    core, _, pre = core.partition("-")
    parts = core.split(".")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        raise ValueError(f"not a semver version: {text!r}")
    ids = tuple(int(i) if i.isdigit() else i for i in pre.split(".")) if pre else ()
    return (int(parts[0]), int(parts[1]), int(parts[2]), ids)


def _pre_key(pre):
    # A release sorts after its pre-releases; numeric identifiers before alphanumeric ones.
    if not pre:
        return (1,)
    return (0,) + tuple((0, i, "") if isinstance(i, int) else (1, 0, i) for i in pre)


def version_key(v):
    return (v[0], v[1], v[2], _pre_key(v[3]))


COMPARATOR = re.compile(r"^\s*(>=|<=|>|<|=|\^|~)?\s*(\d+|\*)(?:\.(\d+|\*))?(?:\.(\d+|\*))?(?:-([0-9A-Za-z.-]+))?\s*$")


def parse_requirement(text):
    """A requirement (`>= 1.2, < 1.4.1`) as a list of comparators (op, major, minor, patch, pre),
    minor and patch None where left out; a bare version means `^` (as in Cargo)."""
    out = []
    for part in text.split(","):
        if not part.strip():
            continue
        m = COMPARATOR.match(part)
        if not m:
            raise ValueError(f"unsupported version requirement: {text!r}")
        op, major, minor, patch, pre = m.groups()
        if major == "*":
            continue  # matches everything
        num = lambda s: None if s in (None, "*") else int(s)  # noqa: E731
        ids = tuple(int(i) if i.isdigit() else i for i in pre.split(".")) if pre else ()
        out.append((op or "^", int(major), num(minor), num(patch), ids))
    return out


def _matches_comparator(c, v):
    op, major, minor, patch, pre = c
    key = version_key(v)
    low = lambda a, b, c_, p=(): version_key((a, b, c_, p))  # noqa: E731
    if op == "=":
        if minor is None:
            return v[0] == major
        if patch is None:
            return v[0] == major and v[1] == minor
        return key == low(major, minor, patch, pre)
    if op in (">", ">="):
        if op == ">" and minor is None:
            return v[0] > major
        if op == ">" and patch is None:
            return (v[0], v[1]) > (major, minor)
        bound = low(major, minor or 0, patch or 0, pre)
        return key > bound if op == ">" else key >= bound
    if op in ("<", "<="):
        if op == "<=" and minor is None:
            return v[0] <= major
        if op == "<=" and patch is None:
            return (v[0], v[1]) <= (major, minor)
        bound = low(major, minor or 0, patch or 0, pre)
        return key < bound if op == "<" else key <= bound
    if op == "~":
        if not key >= low(major, minor or 0, patch or 0, pre):
            return False
        return v[0] == major if minor is None else (v[0], v[1]) == (major, minor)
    # Caret: the leftmost non-zero part given must stay the same.
    if not key >= low(major, minor or 0, patch or 0, pre):
        return False
    if major > 0 or minor is None:
        return v[0] == major
    if minor > 0 or patch is None:
        return (v[0], v[1]) == (major, minor)
    return (v[0], v[1], v[2]) == (major, minor, patch)


def matches(requirement, version):
    """Whether `version` (text) satisfies `requirement` (text), by semver precedence alone. Unlike
    Cargo's resolver, a pre-release is not kept out of a range that names no pre-release:
    cargo-audit decides so too (`0.7.0-rc2` is patched by `>= 0.6.0`)."""
    v = parse_version(version)
    return all(_matches_comparator(c, v) for c in parse_requirement(requirement))


# --- the database ---------------------------------------------------------------------------------

def front_matter(path):
    """The TOML front matter of an advisory file."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    m = re.match(r"\s*```toml\s*\n(.*?)\n```", text, re.S)
    if not m:
        raise ValueError(f"{path}: no ```toml front matter")
    return tomllib.loads(m.group(1))


def advisories_for(db, name):
    """Every advisory of crate `name` as (id, informational kind or None, withdrawn, patched,
    unaffected, path)."""
    folder = os.path.join(db, "crates", name)
    if not os.path.isdir(folder):
        return []
    out = []
    for file in sorted(os.listdir(folder)):
        if not file.endswith(".md"):
            continue
        path = os.path.join(folder, file)
        data = front_matter(path)
        adv, versions = data.get("advisory", {}), data.get("versions", {})
        kind = adv.get("informational")
        out.append(
            (
                adv.get("id", file[:-3]),
                kind.strip() if isinstance(kind, str) else None,
                bool(adv.get("withdrawn")),
                versions.get("patched", []),
                versions.get("unaffected", []),
                path,
            )
        )
    return out


def affected(version, patched, unaffected):
    return not any(matches(r, version) for r in list(patched) + list(unaffected))


def database_age(db):
    """(date, how it was found) of the copy: SNAPSHOT.txt's first date, else the newest
    advisory's date."""
    snapshot = os.path.join(db, "SNAPSHOT.txt")
    if os.path.isfile(snapshot):
        with open(snapshot, encoding="utf-8") as f:
            m = re.search(r"\d{4}-\d{2}-\d{2}", f.read())
        if m:
            return datetime.date.fromisoformat(m.group(0)), "snapshot date in SNAPSHOT.txt"
    newest = None
    for root, _, files in os.walk(os.path.join(db, "crates")):
        for file in files:
            if file.endswith(".md"):
                date = front_matter(os.path.join(root, file)).get("advisory", {}).get("date")
                if date is not None:
                    date = date if isinstance(date, datetime.date) else datetime.date.fromisoformat(str(date))
                    newest = date if newest is None or date > newest else newest
    return newest, "newest advisory"


def locked_crates(lock):
    """(name, version) of every registry crate of a Cargo.lock."""
    with open(lock, "rb") as f:
        data = tomllib.load(f)
    return [
        (p["name"], p["version"])
        for p in data.get("package", [])
        if str(p.get("source", "")).startswith("registry+") or str(p.get("source", "")).startswith("sparse+")
    ]


def read_allow(path):
    """{advisory id: reason} of the allow file; a line without a reason is an error."""
    allowed = {}
    if not os.path.exists(path):
        return allowed
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            ident, _, reason = line.partition(" ")
            if not re.fullmatch(r"RUSTSEC-\d{4}-\d{4}", ident) or not reason.strip():
                raise ValueError(f"{path}:{n}: expected `RUSTSEC-YYYY-NNNN reason`, found {line!r}")
            allowed[ident] = reason.strip()
    return allowed


def check(db, locks, allowed, out=print):
    """Checks `locks`; returns (failures, warnings, accepted) as lists of message lines."""
    failures, warnings, accepted = [], [], []
    for lock in locks:
        for name, version in sorted(set(locked_crates(lock))):
            for ident, kind, withdrawn, patched, unaffected, _ in advisories_for(db, name):
                if withdrawn or not affected(version, patched, unaffected):
                    continue
                what = "vulnerability" if kind is None else kind
                fix = f"patched: {', '.join(patched)}" if patched else "no patched version"
                line = f"{name} {version} ({lock}): {ident} ({what}; {fix})"
                if ident in allowed:
                    accepted.append(f"{line}: {allowed[ident]}")
                elif kind in FAILING:
                    failures.append(line)
                else:
                    warnings.append(line)
    return failures, warnings, accepted


# --- self-test ----------------------------------------------------------------------------------

def self_test(db):
    """Semver matching on the forms the database uses, the policy on a made-up database, and
    lexical-core 0.7.6 flagged by RUSTSEC-2023-0086 in the real one."""
    cases = [
        (">= 1.0.0", "0.7.6", False), (">= 1.0.0", "1.0.0", True), (">= 1.0.0", "1.0.0-rc.1", False),
        (">= 0.4.2, < 0.5.0", "0.4.9", True), (">= 0.4.2, < 0.5.0", "0.5.0", False),
        ("< 0.5.0, >= 0.4.2", "0.4.1", False), (">= 1.2", "1.2.0", True), ("< 0.3", "0.2.9", True),
        ("^0.3.4", "0.3.9", True), ("^0.3.4", "0.4.0", False), ("^1.2.3", "1.9.0", True),
        ("^ 0.0.3", "0.0.4", False), ("0.7.1", "0.7.5", True), ("0.7.1", "0.8.0", False),
        ("=0.9.8", "0.9.8", True), ("=0.9.8", "0.9.9", False), ("> 1.4.0", "1.4.0", False),
        ("> 1.4.0", "1.4.1", True), (">1", "1.9.0", False), (">1", "2.0.0", True),
        ("<= 0.2.1", "0.2.1", True), ("<= 0.2", "0.2.7", True), ("<= 0.2", "0.3.0", False),
        (">= 0.7.0-alpha.2", "0.7.0-alpha.3", True), (">= 0.7.0-alpha.2", "0.7.0-alpha.1", False),
        (">= 0.7.0-alpha.2", "0.7.0", True), (">= 0.6.0", "0.7.0-rc2", True), ("< 0.7.0", "0.7.0-rc2", True),
        (">= 1.0.0, < 1.1.0-rc.1", "1.1.0-rc.0", True), ("~1.2.3", "1.2.9", True), ("~1.2.3", "1.3.0", False),
        (">= 1.0.0-rc.2", "1.0.0-rc.10", True), (">= 2", "2.0.1", True), ("*", "9.9.9", True),
    ]
    for req, version, expected in cases:
        assert matches(req, version) == expected, f"{version} in {req!r}: expected {expected}"
    assert version_key(parse_version("1.0.0-alpha")) < version_key(parse_version("1.0.0-alpha.1"))
    assert version_key(parse_version("1.0.0-beta.11")) > version_key(parse_version("1.0.0-beta.2"))
    assert version_key(parse_version("1.0.0-rc.1")) < version_key(parse_version("1.0.0"))

    with tempfile.TemporaryDirectory() as tmp:
        lock = os.path.join(tmp, "Cargo.lock")
        registry = 'source = "registry+https://github.com/rust-lang/crates.io-index"'
        with open(lock, "w") as f:
            for name, version in [("lexical-core", "0.7.6"), ("lexical-core", "1.0.6"), ("fake", "1.0.0")]:
                f.write(f'[[package]]\nname = "{name}"\nversion = "{version}"\n{registry}\n\n')
            f.write('[[package]]\nname = "rollbem"\nversion = "0.1.0"\n')
        # The real database: lexical-core 0.7.6 is unsound by RUSTSEC-2023-0086, 1.0.6 is not.
        failures, _, _ = check(db, [lock], {})
        assert any(f.startswith("lexical-core 0.7.6") and "RUSTSEC-2023-0086" in f for f in failures), failures
        assert not any(f.startswith("lexical-core 1.0.6") for f in failures), failures
        # Accepted in the allow file: reported, not failing.
        failures, _, accepted = check(db, [lock], {"RUSTSEC-2023-0086": "test"})
        assert not any("RUSTSEC-2023-0086" in f for f in failures) and any("RUSTSEC-2023-0086" in a for a in accepted)

        # A made-up database for the policy: a vulnerability fails, unmaintained warns,
        # withdrawn is ignored, an unaffected range spares.
        fake_db = os.path.join(tmp, "db")
        os.makedirs(os.path.join(fake_db, "crates", "fake"))
        for ident, extra, versions in [
            ("RUSTSEC-2099-0001", "", 'patched = [">= 1.0.1"]'),
            ("RUSTSEC-2099-0002", 'informational = "unmaintained"', "patched = []"),
            ("RUSTSEC-2099-0003", 'withdrawn = "2099-02-01"', "patched = []"),
            ("RUSTSEC-2099-0004", "", 'patched = [">= 2.0.0"]\nunaffected = ["< 0.9"]'),
            ("RUSTSEC-2099-0005", "", 'patched = []\nunaffected = ["^1.0.0"]'),
        ]:
            with open(os.path.join(fake_db, "crates", "fake", ident + ".md"), "w") as f:
                f.write(f'```toml\n[advisory]\nid = "{ident}"\npackage = "fake"\ndate = "2099-01-0{ident[-1]}"\n{extra}\n\n[versions]\n{versions}\n```\n\n# Made up\n')
        failures, warnings, _ = check(fake_db, [lock], {})
        ids = lambda lines: sorted(re.findall(r"RUSTSEC-\d{4}-\d{4}", " ".join(lines)))  # noqa: E731
        assert ids(failures) == ["RUSTSEC-2099-0001", "RUSTSEC-2099-0004"], failures
        assert ids(warnings) == ["RUSTSEC-2099-0002"], warnings
        assert database_age(fake_db) == (datetime.date(2099, 1, 5), "newest advisory")

        allow = os.path.join(tmp, "allow.txt")
        with open(allow, "w") as f:
            f.write("# comment\nRUSTSEC-2099-0001\n")
        try:
            read_allow(allow)
            raise AssertionError("an allow entry without a reason must be refused")
        except ValueError as e:
            assert "reason" in str(e)
    print(f"self-test: {len(cases)} requirement cases and the policy checks passed")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("locks", nargs="*", default=["Cargo.lock"], help="lock files (default: Cargo.lock)")
    ap.add_argument("--db", required=True, help="the advisory database folder (holding crates/)")
    ap.add_argument("--allow", default=DEFAULT_ALLOW, help="accepted advisories (default: %(default)s)")
    ap.add_argument("--self-test", action="store_true", help="test the matching and the policy, then exit")
    args = ap.parse_args()

    if not os.path.isdir(os.path.join(args.db, "crates")):
        print(
            f"error: no advisory database at {args.db} (expected a copy of the RustSec advisory-db with "
            "its crates/ folder); give its path with --db",
            file=sys.stderr,
        )
        return 2
    if args.self_test:
        self_test(args.db)
        return 0
    try:
        allowed = read_allow(args.allow)
        date, how = database_age(args.db)
        for lock in args.locks:
            if not os.path.isfile(lock):
                raise OSError(f"no lock file {lock}")
        failures, warnings, accepted = check(args.db, args.locks, allowed)
    except (OSError, ValueError, tomllib.TOMLDecodeError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    age = f"{date} ({how}), {(datetime.date.today() - date).days} days old" if date else "of unknown date"
    print(f"advisory database: {os.path.abspath(args.db)}, {age}")
    crates = sum(len(set(locked_crates(lock))) for lock in args.locks)
    for line in accepted:
        print(f"accepted: {line}")
    for line in warnings:
        print(f"warning: {line}")
    for line in failures:
        print(f"ADVISORY: {line}")
    if failures:
        print(
            f"{len(failures)} locked crate version(s) with a vulnerability or soundness advisory: update "
            f"them (cargo update -p NAME), or accept the advisory with a reason in {os.path.relpath(args.allow)}",
            file=sys.stderr,
        )
        return 1
    print(f"advisories: {crates} locked crate versions checked, {len(warnings)} warning(s), none failing")
    return 0


if __name__ == "__main__":
    sys.exit(main())
