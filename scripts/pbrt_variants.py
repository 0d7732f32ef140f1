"""pbrt-v4 scene files rewritten for timing runs: another Film resolution,
Sampler or Integrator, the rest of the file unchanged.

A scene names its meshes and textures relative to its own directory, so a
rewritten file goes into a directory of its own whose other entries are
symbolic links to the original directory's entries: lowdisc and pbrt-v4 then
read the same rewritten file and resolve the same relative paths. Directives
are found by a plain pattern (name, quoted type, then `"type name" value`
parameters), which the scene files used here satisfy; a file where the
pattern finds nothing to rewrite is refused rather than rendered unchanged.
"""

import os
import re

# One parameter: "type name" followed by [ ... ], a quoted string or a number.
PARAM = r'\s*"[^"]*"\s*(?:\[[^\]]*\]|"[^"]*"|[-+0-9.eE]+)'


def directive(name):
    """Pattern of directive `name` with its type and parameter list."""
    return re.compile(r'^[ \t]*%s\s+"([^"]*)"((?:%s)*)' % (name, PARAM), re.M)


def set_directive(text, name, replacement):
    """`text` with its first `name` directive replaced by `replacement`, or
    with `replacement` put before WorldBegin when the file has none."""
    m = directive(name).search(text)
    if m:
        return text[:m.start()] + replacement + text[m.end():]
    world = re.search(r"^[ \t]*WorldBegin", text, re.M)
    if not world:
        raise ValueError("no %s directive and no WorldBegin" % name)
    return text[:world.start()] + replacement + "\n" + text[world.start():]


def strip_comments(text):
    """`text` without its `#` comments (a `#` inside a quoted string stays)."""
    return re.sub(r'("[^"\n]*")|#[^\n]*', lambda m: m.group(1) or "", text)


def set_resolution(text, width, height):
    """`text` with its Film's x and y resolution set to width and height
    (comments are dropped; a resolution the Film leaves at its default is
    added)."""
    text = strip_comments(text)
    for axis, value in (("x", width), ("y", height)):
        pattern = r'"integer %sresolution"\s*\[?\s*\d+\s*\]?' % axis
        param = '"integer %sresolution" [ %d ]' % (axis, value)
        text, n = re.subn(pattern, param, text)
        if n == 0:
            text, n = re.subn(r'^([ \t]*Film\s+"[^"]*")', r"\1 " + param, text, flags=re.M)
        if n != 1:
            raise ValueError("%d Film %sresolution parameters, expected 1" % (n, axis))
    return text


def path_integrator(text, extra=""):
    """`text` whose Integrator is pbrt-v4's "path" (inserted, keeping pbrt-v4's
    default maxdepth 5, when the file names none; a "volpath" becomes "path"
    with its parameters kept), with the parameters `extra` appended."""
    m = directive("Integrator").search(text)
    params = m.group(2) if m else ""
    if m and m.group(1) not in ("path", "volpath"):
        raise ValueError('Integrator "%s" is neither path nor volpath' % m.group(1))
    return set_directive(text, "Integrator", 'Integrator "path"%s%s' % (params, extra))


def write_variant(src, out_dir, res=None, sampler=None, spp=None, integrator_extra=None):
    """Writes pbrt-v4 file `src` rewritten into directory `out_dir` (created;
    every other entry of src's directory is linked there) and returns the new
    file's path. res: (width, height) or None; sampler: a pbrt-v4 sampler name
    (with `spp` pixel samples) replacing the file's Sampler, or None;
    integrator_extra: None to keep the Integrator, else parameters (possibly
    "") appended to the "path" integrator `path_integrator` makes."""
    with open(src) as f:
        text = f.read()
    if res:
        text = set_resolution(text, *res)
    if sampler:
        text = set_directive(text, "Sampler",
                             'Sampler "%s" "integer pixelsamples" [ %d ]' % (sampler, spp))
    if integrator_extra is not None:
        text = path_integrator(text, integrator_extra)
    os.makedirs(out_dir)
    src_dir = os.path.dirname(os.path.abspath(src))
    name = os.path.basename(src)
    for entry in os.listdir(src_dir):
        if entry != name:
            os.symlink(os.path.join(src_dir, entry), os.path.join(out_dir, entry))
    out = os.path.join(out_dir, name)
    with open(out, "w") as f:
        f.write(text)
    return out


def parse_res(text):
    """(width, height) of "WxH"."""
    w, h = text.lower().split("x")
    return int(w), int(h)
