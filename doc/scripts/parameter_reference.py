#!/usr/bin/env python3
"""Write doc/reference/*.md, one page per parameter section, from
doc/parameters.prm (the output of 'rubberdyn --print-parameters').

    python3 doc/scripts/parameter_reference.py [doc/parameters.prm [doc/reference]]

Each entry gets its meaning (the documentation string the executable
prints), its unit (the first parenthesised unit of that string, '-' for a
number without one; empty where the entry is not a number), its default and
its pattern (deal.II's description of the allowed values). The text comes
from the executable alone, so a page is as current as doc/parameters.prm;
run this after regenerating it ('--check-stale' exits 1, naming the page,
when a page differs from what it would write). Only the short
introductions below are written by hand.
"""
import os
import re
import sys

# Pages: (file, section path in the parameter file, title, introduction).
# A section's subsections go on its page unless they have a page of their own.
PAGES = [
    ("global.md", "", "Study (top level)",
     "The one entry outside every subsection: which study runs. A `Model` "
     "study is your own mesh and model (`doc/model.md`, `doc/tutorial/`)."),
    ("mesh.md", "Mesh", "Mesh",
     "The Gmsh mesh of a `Model` study: physical volume tags become material "
     "ids, physical surface tags boundary ids (`doc/model.md`, section 1; "
     "`doc/tutorial/1_model.md`)."),
    ("model.md", "Model", "Model",
     "Model-wide settings of a `Model` study."),
    ("parts.md", "Parts", "Parts",
     "One subsection per part, named in `Parts/Names`: its cells (material "
     "ids), its element formulation, its constitutive law with its constants, "
     "its initial velocity; a rigid part (`Model = Rigid`) with its motion. "
     "User's guide: `doc/model.md`, \"Parts\"."),
    ("boundary_conditions.md", "Boundary conditions", "Boundary conditions",
     "One subsection per condition, named in `Boundary conditions/Names`: "
     "fixed, prescribed displacement or velocity, symmetry, follower pressure "
     "or traction on the faces of some boundary ids, functions of x, y, z and "
     "t. User's guide: `doc/model.md`, \"Boundary conditions\"; the hand-off's "
     "rule for preloads: `doc/quasi_static.md`, \"The hand-off\"."),
    ("rigid_surfaces.md", "Rigid surfaces", "Rigid surfaces",
     "Analytic rigid planes and cylinders in node-to-surface penalty contact "
     "with the solid, each on a rigid body of its own or on a rigid part. "
     "User's guide: `doc/model.md`, \"Rigid surfaces\"; their penalty and "
     "initial penetrations: `contact.md` (this folder)."),
    ("contact_pairs.md", "Contact pairs", "Contact pairs",
     "Mortar (segment-to-segment) contact between surfaces of the mesh: "
     "frictionless, Coulomb or tied. User's guide: `doc/contact.md`; "
     "verification: `doc/verification/contact.md`."),
    ("contact.md", "Contact", "Contact",
     "Settings shared by all rigid surfaces (not by the mortar `Contact "
     "pairs`, which have their own)."),
    ("pretension_sections.md", "Pretension sections", "Pretension sections",
     "Bolt pretension in the quasi-static schemes. User's guide: "
     "`doc/quasi_static.md`, \"Bolt pretension\"."),
    ("cross_sections.md", "Cross sections", "Cross sections",
     "Section forces for the time history of explicit runs (LS-DYNA's "
     "*DATABASE_CROSS_SECTION). User's guide: `doc/model.md`, \"Cross "
     "sections\"."),
    ("time_integration.md", "Time integration", "Time integration",
     "The scheme (explicit, quasi-static, or quasi-static then explicit) and "
     "the explicit run's settings. The Newton solver's settings are on "
     "[quasi_static.md](quasi_static.md). User's guides: `doc/model.md`, "
     "`doc/quasi_static.md`."),
    ("quasi_static.md", "Time integration/Quasi-static",
     "Time integration / Quasi-static",
     "The Newton-Raphson solver of `Scheme = quasi-static` and of the load "
     "path of `quasi-static then explicit`: load steps, convergence, linear "
     "solver. User's guide: `doc/quasi_static.md`."),
    ("output.md", "Output", "Output",
     "What a run writes and where: `time_history.csv`, the ParaView series, "
     "checkpoints. The columns: `doc/model.md`, section 4 (explicit), "
     "`doc/quasi_static.md`, \"Output\"."),
    ("drop_test.md", "Drop test", "Drop test",
     "The built-in study of the reference study's chapter 4 (`set Study = "
     "Drop test`, the default): `doc/drop_test.md`."),
    ("materials.md", "Materials", "Materials",
     "The materials of the built-in studies: `Rubber` for the `Drop test`, "
     "`Specimen` for the `Material point` study. A `Model` study sets its "
     "laws per part instead ([parts.md](parts.md))."),
    ("material_point.md", "Material point", "Material point",
     "The `Material point` study: one point of `Materials/Specimen` under a "
     "homogeneous deformation."),
]

UNITS = {"mm", "ms", "kg", "kN", "GPa", "J", "rad", "s", "-", "mm/ms",
         "kg/mm^3", "1/GPa", "ms/mm", "kN mm", "mm^2", "mm/ms^2", "GPa/mm",
         "rad/ms", "kN/kN", "J/J", "kg mm/ms", "mm/ms = m/s"}


def parse(path):
    """Entries as (section path, name, doc, pattern, default), and the
    section paths in file order."""
    entries, sections, stack, comment = [], [""], [], []
    with open(path) as f:
        lines = f.read().splitlines()
    for line in lines:
        s = line.strip()
        if s.startswith("#"):
            comment.append(s[1:].strip() if len(s) > 1 else "")
            continue
        if s.startswith("subsection "):
            stack.append(s[len("subsection "):])
            sections.append("/".join(stack))
            comment = []
        elif s == "end":
            stack.pop()
            comment = []
        elif s.startswith("set "):
            name, _, default = s[4:].partition("=")
            doc, pattern, in_allowed = [], [], False
            for c in comment:
                if c.startswith("Allowed:"):
                    in_allowed = True
                    pattern.append(c[len("Allowed:"):].strip())
                elif in_allowed:
                    pattern.append(c)
                else:
                    doc.append(c)
            entries.append(("/".join(stack), name.strip(), " ".join(doc),
                            " ".join(pattern), default.strip()))
            comment = []
        elif not s:
            if not stack:   # the file's header ends at the first blank line
                comment = []
    return entries, sections


# Where the first parenthesised unit is not the entry's (a relative
# tolerance whose documentation names the kN of the norms it compares), or
# the documentation names none: (section or '*', entry) -> unit.
UNIT_OVERRIDES = {
    ("Time integration/Quasi-static", "Residual tolerance"): "- (relative)",
    ("Time integration", "Time step scale factor"): "-",
    ("*", "Poisson's ratio"): "-",
    ("*", "Shore A hardness"): "Shore A",
    ("*", "Direction"): "- (a direction)",
    ("*", "Normal"): "- (a direction)",
    ("Pretension sections/<name>", "Lock time"): "- (pseudo-time)",
    ("Drop test", "Impact velocity"): "mm/ms (= m/s)",
    ("Rigid surfaces/<name>", "Penalty scale factor"): "- (or 'inherit')",
}


def unit_of(doc, pattern, section="", name=""):
    for key in ((section, name), ("*", name)):
        if key in UNIT_OVERRIDES:
            return UNIT_OVERRIDES[key]
    if not (pattern.startswith("[Double") or pattern.startswith("[Integer")
            or pattern.startswith("[List of <[Double")):
        return ""
    for group in re.findall(r"\(([^()]*)\)", doc):
        for part in re.split(r"[,;]", group):
            token = part.strip()
            if token in UNITS:
                return token
            token = token.split(" ")[0] if token.startswith("-") else token
            if token in UNITS:
                return token
    return "-" if pattern.startswith("[Integer") else ""


def anchor(name):
    return re.sub(r"[^a-z0-9 -]", "", name.lower()).replace(" ", "-")


def page(entries, sections, section, title, intro, own_pages):
    # The section and those of its subsections without a page of their own.
    mine = [s for s in sections
            if (s == section or (section and s.startswith(section + "/"))
                or (not section and s == ""))
            and not any(s == p or s.startswith(p + "/")
                        for p in own_pages if p != section and p and
                        (not section or p.startswith(section + "/")))]
    intro = re.sub(r"`doc/([\w/]+\.md)`", r"[doc/\1](../\1)", intro)
    out = [f"# Parameter reference: {title}", "",
           "<!-- Written by doc/scripts/parameter_reference.py from "
           "doc/parameters.prm; do not edit by hand. -->", "",
           intro, "",
           "Units: mm, ms, kg, kN, GPa (energy in J = kN mm, velocity in "
           "mm/ms = m/s). *Unit* is the one the entry's documentation names "
           "('-': a number without unit); *Allowed* is the pattern the "
           "parameter file is checked against. `<name>` stands for each name "
           "of the section's `Names`. All sections: [README.md](README.md).",
           ""]
    for s in mine:
        rows = [e for e in entries if e[0] == s]
        if not rows:
            continue
        shown = s.replace("/<name>", "/&lt;name&gt;")
        out += [f"## `{s}`" if s else "## Top level", ""]
        for sec, name, doc, pattern, default in rows:
            unit = unit_of(doc, pattern, sec, name)
            out += [f"### {name}", "",
                    doc.replace("<", "&lt;").replace(">", "&gt;"), ""]
            out.append(f"- Default: `{default}`" if default
                       else "- Default: empty")
            if unit:
                out.append(f"- Unit: {unit}")
            out += [f"- Allowed: `{pattern}`",
                    f"- Set as: `subsection {s.replace('/', ' / subsection ')}`"
                    f" … `set {name} = …`" if s else f"- Set as: `set {name} = …`",
                    ""]
    return "\n".join(out).rstrip() + "\n"


def index(pages):
    out = ["# Parameter reference", "",
           "<!-- Written by doc/scripts/parameter_reference.py from "
           "doc/parameters.prm; do not edit by hand. -->", "",
           "One page per section of the parameter file, each entry with its "
           "meaning, unit, default and allowed values, as `rubberdyn "
           "--print-parameters` prints them (`doc/parameters.prm` is that "
           "output, checked by a test). The user's guides say how to combine "
           "them: `doc/model.md`, `doc/contact.md`, `doc/quasi_static.md`; "
           "the tutorial builds a model step by step: `doc/tutorial/`.", "",
           "| page | section |", "|---|---|"]
    for file, section, title, intro in pages:
        out.append(f"| [{file}]({file}) | `{section or '(top level)'}` |")
    return "\n".join(out) + "\n"


def main():
    prm = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--") else "doc/parameters.prm"
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    target = args[1] if len(args) > 1 else "doc/reference"
    check = "--check-stale" in sys.argv
    entries, sections = parse(prm)
    own = [p[1] for p in PAGES]
    covered = set()
    files = {"README.md": index(PAGES)}
    for file, section, title, intro in PAGES:
        text = page(entries, sections, section, title, intro, own)
        files[file] = text
        covered.update(re.findall(r"^## `(.*)`$", text, re.M))
    missing = [s for s in sections if s and s not in covered
               and any(e[0] == s for e in entries)]
    if missing:
        sys.exit("parameter_reference.py: no page for " + ", ".join(missing))
    stale = []
    for file, text in files.items():
        path = os.path.join(target, file)
        if check:
            if not os.path.exists(path) or open(path).read() != text:
                stale.append(path)
        else:
            with open(path, "w") as f:
                f.write(text)
    if stale:
        sys.exit("stale (run doc/scripts/parameter_reference.py): " + ", ".join(stale))


if __name__ == "__main__":
    main()
