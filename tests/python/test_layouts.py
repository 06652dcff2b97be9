"""One source for each output layout: the enums of the style headers.

tests/print_layouts.cpp prints the positions of the vectors of compute
grflow/network, fix grflow/shear, fix grflow/compress and fix grflow/wall
as the compiler sees them in the headers (LAYOUTS: its path).  Every other
place that writes a layout out is checked against them, so that a change
of any one place alone fails here:

- inputs/names.lmp: the 1-based c_net[...], f_shear[...], f_comp[...] of
  its variables; its P_c assume the compute's default cmax, which the
  shear deck must keep;
- inputs/walls.lmp: f_walls[...] of zlo and zhi;
- inputs/shear.lmp: the series' title against the values its print line
  writes (names.lmp's variables, so the title's columns are tied to the
  headers through names.lmp);
- analysis/ (SERIES_COLUMNS, PC_COLUMNS, read by parsing, not importing:
  no path or install state is assumed), tests/python/runfiles.py
  (COLUMNS, the series columns of both hosts' deck tests) and the series table of inputs/README.md, against that title.

Each check returns its problems; test_checks_can_fail moves one place at
a time and shows that the checks see it.
"""

import ast
import os
import re
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
INPUTS = os.environ.get("GRFLOW_INPUTS", os.path.join(ROOT, "inputs"))
LAYOUTS = os.environ.get("LAYOUTS")

# the variables of names.lmp: the output they name (compute or fix ID of
# the decks, layout, entry of the header's enum)
NAMES = {
    "net_sxx": ("c_net", "network", "SXX"),
    "net_syy": ("c_net", "network", "SYY"),
    "net_szz": ("c_net", "network", "SZZ"),
    "net_sxy": ("c_net", "network", "SXY"),
    "net_sxz": ("c_net", "network", "SXZ"),
    "net_syz": ("c_net", "network", "SYZ"),
    "net_p": ("c_net", "network", "PRESS"),
    "net_tau": ("c_net", "network", "TAU"),
    "net_Np": ("c_net", "network", "NP"),
    "net_floaters": ("c_net", "network", "NFLOAT"),
    "net_Nc": ("c_net", "network", "NCONTACT"),
    "net_zg": ("c_net", "network", "ZG"),
    "net_ac": ("c_net", "network", "AC"),
    "shear_direction": ("f_shear", "shear", "DIRECTION"),
    "shear_reversals": ("f_shear", "shear", "REVERSALS"),
    "shear_xw": ("f_shear", "shear", "XWALL"),
    "shear_gamma": ("f_shear", "shear", "GAMMA"),
    "shear_ru": ("f_shear", "shear", "RU"),
    "shear_step_il": ("f_shear", "shear", "STEP_IL"),
    "shear_N_il": ("f_shear", "shear", "N_IL"),
    "shear_N": ("f_shear", "shear", "N_EVENT"),
    "shear_done": ("f_shear", "shear", "DONE"),
    "shear_event": ("f_shear", "shear", "EVENT"),
    "comp_ready": ("f_comp", "compress", "CONVERGED"),
    "comp_sxx": ("f_comp", "compress", "SXX"),
    "comp_syy": ("f_comp", "compress", "SYY"),
    "comp_szz": ("f_comp", "compress", "SZZ"),
    "comp_err": ("f_comp", "compress", "ERRMAX"),
    "comp_ke_ratio": ("f_comp", "compress", "RATIO"),
    "comp_e": ("f_comp", "compress", "VOID"),
}
# P_c: net_P<c> is entry PC0 + c, c = 0 ... cmax (the last: cmax or more)
PC_NAME = re.compile(r"^net_P(\d+)$")

# walls.lmp: the wall positions of fix walls
WALLS = {"zlo": ("f_walls", "wall", "LO_Z"), "zhi": ("f_walls", "wall", "HI_Z")}

# doc/pair_granular_grflow.rst, "Per-contact output": the bullet of each
# entry of single()'s extra values (compute pair/local p1 ...), found by a
# phrase of its text
SINGLE_DOC = {
    "FS_X": "components of the sliding force", "FS_LEN": "magnitude of the sliding force",
    "FR_X": "components of the rolling resistance",
    "FR_LEN": "magnitude of the rolling resistance", "TWIST": "twisting torque",
    "DX": "branch vector", "FO": "signed torsion force",
    "FO_LEN": "magnitude of the torsion force", "FN": "the normal force",
}

# the series' columns: what the print line of shear.lmp writes for each
SERIES_VALUES = {
    "step": "step", "time": "time", "reversals": "v_shear_reversals",
    "direction": "v_shear_direction", "x_w": "v_shear_xw", "gamma": "v_shear_gamma",
    "tau": "v_net_tau", "p": "v_net_p", "r_u": "v_shear_ru", "z_g": "v_net_zg",
    "a_c": "v_net_ac", "N_c": "v_net_Nc", "N_p": "v_net_Np", "floaters": "v_net_floaters",
    "sxx": "v_net_sxx", "syy": "v_net_syy", "szz": "v_net_szz", "sxy": "v_net_sxy",
    "sxz": "v_net_sxz", "syz": "v_net_syz", "zlo": "v_zlo", "zhi": "v_zhi",
    "inertial": "v_inertial",
}
PC_COLUMN = re.compile(r"^P(\d+)$")


def read(path):
    with open(path) as f:
        return f.read()


@pytest.fixture(scope="module")
def layouts():
    """{layout: {entry: position}} from the compiled headers."""
    if not LAYOUTS or not os.path.exists(LAYOUTS):
        pytest.skip("needs LAYOUTS, the print_layouts program of the build")
    out = subprocess.run([LAYOUTS], check=True, capture_output=True, text=True).stdout
    result = {}
    for line in out.splitlines():
        layout, name, value = line.split()
        result.setdefault(layout, {})[name] = int(value)
    return result


# ---------------------------------------------------------------- checks

def lmp_variables(text):
    """equal-style variables NAME equal ID[N] of a deck: {NAME: (ID, N)}."""
    found = {}
    for m in re.finditer(r"^variable\s+(\w+)\s+equal\s+([cf]_\w+)\[(\d+)\]", text, re.M):
        found[m.group(1)] = (m.group(2), int(m.group(3)))
    return found


def check_names(text, lay):
    problems = []
    found = lmp_variables(text)
    cmax = lay["network"]["CMAX"]
    pcs = set()
    for name, (src, index) in found.items():
        m = PC_NAME.match(name)
        if m:
            c = int(m.group(1))
            pcs.add(c)
            want = ("c_net", lay["network"]["PC0"] + c + 1)
        elif name in NAMES:
            s, layout, entry = NAMES[name]
            want = (s, lay[layout][entry] + 1)
        else:
            problems.append(f"names.lmp: {name} = {src}[{index}] is not known to this test "
                            "(add it to NAMES with its header entry)")
            continue
        if (src, index) != want:
            problems.append(f"names.lmp: {name} = {src}[{index}], the header says "
                            f"{want[0]}[{want[1]}]")
    for name in NAMES:
        if name not in found:
            problems.append(f"names.lmp: {name} is missing")
    if pcs != set(range(cmax + 1)):
        problems.append(f"names.lmp: P_c for c = {sorted(pcs)}, the compute's default cmax "
                        f"{cmax} gives 0 ... {cmax}")
    return problems


def check_walls(text, lay):
    problems = []
    found = lmp_variables(text)
    for name, (s, layout, entry) in WALLS.items():
        want = (s, lay[layout][entry] + 1)
        if found.get(name) != want:
            problems.append(f"walls.lmp: {name} = {found.get(name)}, the header says {want}")
    return problems


def deck_command(text, pattern):
    """the command of a deck that matches pattern, its & continuations joined."""
    joined = re.sub(r"&\s*\n", " ", text)
    for line in joined.splitlines():
        if re.match(pattern, line):
            return line
    return None


def series_of(shear_text):
    """(title columns, printed values) of the series' fix print in shear.lmp."""
    cmd = deck_command(shear_text, r"^fix\s+series\s+all\s+print\b")
    if cmd is None:
        return None, None
    quoted = re.findall(r'"([^"]*)"', cmd)
    line = next((q for q in quoted if "$(" in q), "")
    title = next((q for q in quoted if q.startswith("#")), "")
    values = [v.split(":")[0] for v in re.findall(r"\$\(([^)]*)\)", line)]
    return title.lstrip("#").split(), values


def check_series(shear_text, names_text, lay):
    problems = []
    title, values = series_of(shear_text)
    if title is None:
        return ["shear.lmp: no fix series all print"]
    if len(title) != len(values):
        problems.append(f"shear.lmp: the title has {len(title)} columns, the print line "
                        f"writes {len(values)} values")
    for k, (column, value) in enumerate(zip(title, values)):
        m = PC_COLUMN.match(column)
        want = f"v_net_P{m.group(1)}" if m else SERIES_VALUES.get(column)
        if want != value:
            problems.append(f"shear.lmp: column {k + 1} is titled {column} but holds "
                            f"$({value}), expected $({want})")
    # the P_c of the series need the compute's default cmax
    net = deck_command(shear_text, r"^compute\s+net\s")
    m = re.search(r"\bcmax\s+(\S+)", net or "")
    cmax = lay["network"]["CMAX"]
    if m and m.group(1) != str(cmax):
        problems.append(f"shear.lmp: compute net has cmax {m.group(1)}; names.lmp and the "
                        f"series' P_c assume {cmax}")
    pcs = [c for c in title if PC_COLUMN.match(c)]
    if pcs != [f"P{c}" for c in range(cmax + 1)]:
        problems.append(f"shear.lmp: P_c columns {pcs}, expected P0 ... P{cmax}")
    # every variable the line prints that names.lmp defines is checked there
    known = lmp_variables(names_text)
    for value in values:
        if value.startswith("v_net_") and value[2:] not in known:
            problems.append(f"shear.lmp: {value} is not a variable of names.lmp")
    return problems


def assigned_value(path, name):
    """the value of a module-level NAME = <expression> of a Python file,
    evaluated without importing the module (the expression may use only
    literals, tuple, list, range and str methods)."""
    tree = ast.parse(read(path))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == name for t in node.targets):
            code = compile(ast.Expression(node.value), path, "eval")
            return eval(code, {"__builtins__": {"tuple": tuple, "list": list,
                                                "range": range, "str": str}})
    return None


def analysis_module():
    """the file of analysis/ that defines SERIES_COLUMNS."""
    for dirpath, _, files in os.walk(os.path.join(ROOT, "analysis")):
        if "tests" in dirpath.split(os.sep):
            continue
        for f in sorted(files):
            if f.endswith(".py") and "SERIES_COLUMNS =" in read(os.path.join(dirpath, f)):
                return os.path.join(dirpath, f)
    return None


def readme_series(text):
    """the columns of the series table of inputs/README.md, by number."""
    section = text.split("### `series.txt`", 1)[-1].split("\n### ", 1)[0]
    columns = {}
    for m in re.finditer(r"^\|\s*(\d+)(?:-(\d+))?\s*\|\s*`([^`]*)`", section, re.M):
        first, last = int(m.group(1)), int(m.group(2) or m.group(1))
        names = m.group(3).split()
        if "..." in names:    # P0 ... P12
            a, b = PC_COLUMN.match(names[0]), PC_COLUMN.match(names[-1])
            names = [f"P{c}" for c in range(int(a.group(1)), int(b.group(1)) + 1)]
        if len(names) != last - first + 1:
            columns[first] = f"<{m.group(0)}: {len(names)} names for {last - first + 1} numbers>"
            continue
        for k, name in enumerate(names):
            columns[first + k] = name
    return [columns.get(k + 1) for k in range(max(columns))] if columns else []


def check_columns(title, series_columns, pc_columns, protocol_columns, readme_columns):
    problems = []
    for where, cols in (("analysis SERIES_COLUMNS", series_columns),
                        ("tests/python/runfiles.py COLUMNS", protocol_columns),
                        ("inputs/README.md series table", readme_columns)):
        if list(cols or []) != list(title):
            problems.append(f"{where}: {list(cols or [])} is not the series title {title}")
    pcs = [c for c in title if PC_COLUMN.match(c)]
    if list(pc_columns or []) != pcs:
        problems.append(f"analysis PC_COLUMNS: {list(pc_columns or [])}, the title's are {pcs}")
    return problems


def check_single_doc(text, lay):
    """the pair style's doc page against GRFLOW::SingleLayout: its count of
    extra values and the p number of each bullet"""
    problems = []
    section = text.split("**Per-contact output.**", 1)[-1].split("----------", 1)[0]
    n = lay["single"]["NVALUES"]
    m = re.search(r"and (\d+)\s+extra values, accessible as \*p1\* to \*p(\d+)\*", section)
    if not m or int(m.group(1)) != n or int(m.group(2)) != n:
        problems.append(f"pair_granular_grflow.rst: the count of extra values is not {n}")
    bullets = re.findall(r"^\* (p\d+(?:, p\d+)*) = (.*)$", section, re.M)
    for entry, phrase in SINGLE_DOC.items():
        first = [int(ps.split(",")[0][1:]) for ps, what in bullets if phrase in what]
        want = lay["single"][entry] + 1
        if first != [want]:
            problems.append(f"pair_granular_grflow.rst: '{phrase}' is p{first}, the header "
                            f"says p{want}")
    return problems


# ---------------------------------------------------------------- the places

@pytest.fixture(scope="module")
def places():
    module = analysis_module()
    return {
        "names": read(os.path.join(INPUTS, "names.lmp")),
        "walls": read(os.path.join(INPUTS, "walls.lmp")),
        "shear": read(os.path.join(INPUTS, "shear.lmp")),
        "readme": read(os.path.join(INPUTS, "README.md")),
        "series_columns": module and assigned_value(module, "SERIES_COLUMNS"),
        "pc_columns": module and assigned_value(module, "PC_COLUMNS"),
        "protocol_columns": assigned_value(os.path.join(HERE, "runfiles.py"), "COLUMNS"),
        "pair_doc": read(os.path.join(ROOT, "doc", "pair_granular_grflow.rst")),
    }


def all_problems(p, lay):
    title, _ = series_of(p["shear"])
    return (check_names(p["names"], lay) + check_walls(p["walls"], lay)
            + check_series(p["shear"], p["names"], lay)
            + check_columns(title or [], p["series_columns"], p["pc_columns"],
                            p["protocol_columns"], readme_series(p["readme"]))
            + check_single_doc(p["pair_doc"], lay))


def test_headers_are_contiguous(layouts):
    """The header enums the other places are read against: each layout
    numbers its entries 0, 1, 2, ... (no gap a deck could fall into)."""
    for layout, entries in layouts.items():
        values = sorted(v for k, v in entries.items() if k not in ("CMAX", "SIZE"))
        assert values == list(range(len(values))), layout
    assert layouts["network"]["SIZE"] == layouts["network"]["PC0"] + layouts["network"]["CMAX"] + 1


def test_every_place_agrees_with_the_headers(places, layouts):
    assert analysis_module(), "no file of analysis/ defines SERIES_COLUMNS"
    problems = all_problems(places, layouts)
    assert not problems, "\n".join(problems)


def test_readme_examples_agree_with_names(places):
    """inputs/README.md's examples "`v_NAME` for `ID[N]`" are names.lmp's."""
    known = lmp_variables(places["names"])
    examples = re.findall(r"`v_(\w+)` for `([cf]_\w+)\[(\d+)\]`", places["readme"])
    for name, src, index in examples:
        assert known.get(name) == (src, int(index)), name


def test_checks_can_fail(places, layouts):
    """Moving any one place alone is seen."""
    def shift_first_index(text, var):
        return re.sub(r"(variable\s+%s\s+equal\s+\w+\[)(\d+)\]" % var,
                      lambda m: m.group(1) + str(int(m.group(2)) + 1) + "]", text, count=1)

    def swap_title(text):
        return text.replace("# step time reversals direction", "# step time direction reversals")

    moved = {
        "names.lmp": dict(places, names=shift_first_index(places["names"], "net_tau")),
        "names.lmp P_c": dict(places, names=shift_first_index(places["names"], "net_P12")),
        "walls.lmp": dict(places, walls=shift_first_index(places["walls"], "zhi")),
        "shear.lmp title": dict(places, shear=swap_title(places["shear"])),
        "shear.lmp cmax": dict(places, shear=re.sub(r"(compute\s+net\s.*grflow/network.*)",
                                                    r"\1 cmax 8", places["shear"])),
        "analysis": dict(places, series_columns=tuple(places["series_columns"][:-1])),
        "analysis P_c": dict(places, pc_columns=tuple(places["pc_columns"][:-1])),
        "runfiles.py": dict(places, protocol_columns=list(places["protocol_columns"])[::-1]),
        "README.md": dict(places, readme=places["readme"].replace("| 7 | `tau` |", "| 7 | `p` |")),
        "pair doc": dict(places, pair_doc=places["pair_doc"].replace("* p15 = :math:`f_n`",
                                                                     "* p14 = :math:`f_n`")),
    }
    for where, p in moved.items():
        assert all_problems(p, layouts), f"moving {where} alone went unseen"
    # and a header entry moved alone: every deck index of it is then off
    lay = {k: dict(v) for k, v in layouts.items()}
    lay["network"]["TAU"] += 1
    assert check_names(places["names"], lay)
    lay = {k: dict(v) for k, v in layouts.items()}
    lay["wall"]["HI_Z"] += 1
    assert check_walls(places["walls"], lay)
    lay = {k: dict(v) for k, v in layouts.items()}
    lay["single"]["TWIST"] += 1
    assert check_single_doc(places["pair_doc"], lay)


def test_pair_local_fields_of_decks_and_examples(layouts):
    """The p numbers that the decks and the pair style's example give
    compute pair/local are GRFLOW::SingleLayout's for what each reads (the
    shear deck: the sliding force on the first atom; the example: the
    magnitudes of the sliding, rolling and torsion forces and the normal
    force)."""
    lay = layouts["single"]

    def p(entry, k=0):
        return f"p{lay[entry] + 1 + k}"

    expected = {
        os.path.join(INPUTS, "shear.lmp"): {
            "pforce": ["dx", "dy", "dz", "force", p("FS_X"), p("FS_X", 1), p("FS_X", 2)]},
        os.path.join(ROOT, "examples", "grflow", "in.pair_granular_grflow"): {
            "c": [p("FS_LEN"), p("FR_LEN"), p("FO_LEN"), p("FN")],
            "c2": [p("FR_LEN"), p("FO_LEN")]},
    }
    for path, computes in expected.items():
        text = read(path)
        for cid, fields in computes.items():
            m = re.search(r"^compute\s+%s\s+\S+\s+pair/local\s+(.*?)\s+cutoff" % cid, text, re.M)
            assert m, f"{path}: no compute {cid} ... pair/local"
            assert m.group(1).split() == fields, f"{path}: compute {cid}: {m.group(1)}, want {fields}"
