"""Checks that ParaView reads a signorini Exodus series as the README says.

    pvpython tools/check_paraview.py [--reader default|ioss|legacy] RESULTS.e RESULTS.steps.csv

Opens RESULTS.e with ParaView's reader (default: the one File > Open and OpenDataFile pick, in
ParaView 5.11 the IOSS reader; `legacy`: the old ExodusIIReader proxy) and compares what it shows
with what the files say (read with the netCDF4 module, Debian's python3-netcdf4) and with the
step table:
  - the time steps are those of the steps table's output steps (every `Output/Exodus Interval`-th
    step and the last one, the interval from the deck in the file's info records), from
    RESULTS.e and all RESULTS.e-s.NNNN together, bit for bit;
  - at every time the mesh (points, cells, coordinates) is that of the file holding the time,
    and its cells are the table's `cells`;
  - the nodal variables (u, v, a; elasticity's u_x, u_y, ... as the vectors u, v, a), the cell
    variables (level; indicator in adaptive runs; the stresses sigma_xx, sigma_yy, sigma_xy,
    sigma_zz, von_mises and the strains eps_xx, eps_yy, eps_xy for elasticity) and, on the side set `contact`, lambda and gap
    equal the file's values bit for bit; the side set's edges are boundary edges of the mesh, as are
    those of the other side sets (the deck's boundary segments), whose sides are the file's;
    min/max lambda and min gap are the table's, and -sum lambda |E| its contact_force;
  - every column of the table but step, t and the timings is a global variable whose value at
    each time is the table's, also through Filters > Plot Global Variables Over Time.
Runs headless (no display or rendering needed). Prints one summary line and exits 0, or exits 1
with one line `check_paraview: FAIL: ...` naming the first failed check.
"""
import csv
import glob
import math
import os
import re
import signal
import sys

signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # output into a closed pipe (| head): end quietly, as tool_errors.py does


def fail(message):
    print("check_paraview: FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def usage():
    print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
    sys.exit(2)


args = sys.argv[1:]
if any(a in ("-h", "--help") for a in args):  # asked for: the description on stdout, exit status 0
    print(__doc__.strip())
    sys.exit(0)
reader_kind = "default"
if len(args) >= 2 and args[0] == "--reader":
    reader_kind = args[1]
    args = args[2:]
if len(args) != 2 or reader_kind not in ("default", "ioss", "legacy"):
    usage()
exodus_path, csv_path = args
if not exodus_path.endswith(".e"):
    fail("%s: give the series' first file, <basename>.e" % exodus_path)
for path in (exodus_path, csv_path):
    if not os.path.isfile(path):
        fail("%s: no such file" % path)

try:
    import numpy as np
    import netCDF4
except ImportError as e:
    fail("this check needs numpy and netCDF4 in pvpython's Python (Debian: python3-netcdf4): %s" % e)
try:
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:
    fail("run this with ParaView's pvpython: %s" % e)


def same(a, b):
    """Bitwise-equal doubles (NaN equals NaN)."""
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def fmt(x):
    return repr(float(x))


# ---------------------------------------------------------------------------------------------
# What the files say (netCDF).

def nc_names(ds, var):
    if var not in ds.variables:
        return []
    return [str(netCDF4.chartostring(row)).strip() for row in ds.variables[var][:]]


def series_files(first):
    rest = []
    for f in glob.glob(glob.escape(first) + "-s.*"):
        suffix = f[len(first) + 3:]
        if suffix.isdigit():
            rest.append((int(suffix), f))
    rest.sort()
    for expected, (number, f) in enumerate(rest, start=1):
        if number != expected:
            fail("%s: the series skips %s-s.%04d" % (f, first, expected))
    return [first] + [f for _, f in rest]


class FileStep:
    """One time of one file of the series, as netCDF reads it."""


def read_series(first):
    steps = []
    info = None
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from tool_errors import classic_netcdf_size  # the size a netCDF classic file's header declares

    for path in series_files(first):
        needed = classic_netcdf_size(path)
        if needed is not None and os.path.getsize(path) < needed:  # netCDF would read zeros for the rest
            fail("%s: cut short: %d bytes, its header needs %d" % (path, os.path.getsize(path), needed))
        try:
            ds = netCDF4.Dataset(path)
        except OSError as e:
            fail("%s: not readable as an Exodus file: %s" % (path, e.strerror or e))
        ds.set_auto_mask(False)
        if info is None:
            info = nc_names(ds, "info_records")
        nodal = nc_names(ds, "name_nod_var")
        cell = nc_names(ds, "name_elem_var")
        side = nc_names(ds, "name_sset_var")
        glob_names = nc_names(ds, "name_glo_var")
        sets = nc_names(ds, "ss_names")
        num_nodes = ds.dimensions["num_nodes"].size
        num_elem = ds.dimensions["num_elem"].size
        x = np.array(ds.variables["coordx"][:], dtype=float)
        y = np.array(ds.variables["coordy"][:], dtype=float)
        conn = np.array(ds.variables["connect1"][:], dtype=np.int64) if "connect1" in ds.variables else None
        ss = sets.index("contact") + 1 if "contact" in sets else None
        set_keys = {name: list(zip(ds.variables["elem_ss%d" % (i + 1)][:].tolist(), ds.variables["side_ss%d" % (i + 1)][:].tolist()))
                    if "elem_ss%d" % (i + 1) in ds.variables else []  # an empty set has no entries
                    for i, name in enumerate(sets)}
        side_keys = set_keys.get("contact")
        for k, t in enumerate(ds.variables["time_whole"][:].tolist()):
            s = FileStep()
            s.path, s.t, s.num_nodes, s.num_elem, s.x, s.y, s.conn = path, float(t), num_nodes, num_elem, x, y, conn
            s.k, s.times_in_file = k, ds.dimensions["time_step"].size
            s.nodal = {n: np.array(ds.variables["vals_nod_var%d" % (i + 1)][k], dtype=float) for i, n in enumerate(nodal)}
            s.cell = {n: np.array(ds.variables["vals_elem_var%deb1" % (i + 1)][k], dtype=float) for i, n in enumerate(cell)}
            s.side_keys = side_keys
            s.set_keys = set_keys
            s.side = {}
            if ss is not None:
                s.side = {n: np.array(ds.variables["vals_sset_var%dss%d" % (i + 1, ss)][k], dtype=float)
                          for i, n in enumerate(side)}
            gv = ds.variables["vals_glo_var"][k].tolist() if glob_names else []
            s.globals = dict(zip(glob_names, [float(v) for v in gv]))
            steps.append(s)
        ds.close()
    return steps, info or []


def exodus_interval(info):
    """Output/Exodus Interval of the deck in the info records (lines continued with a backslash)."""
    text, pending = [], ""
    for line in info:
        if line.endswith("\\"):
            pending += line[:-1]
        else:
            text.append(pending + line)
            pending = ""
    m = re.search(r'name="Exodus Interval" type="int" value="(\d+)"', "\n".join(text))
    return int(m.group(1)) if m else 1


file_steps, info = read_series(exodus_path)
if not file_steps:
    fail("%s: the series has no time steps" % exodus_path)

with open(csv_path, newline="") as f:
    rows = list(csv.DictReader(f))
if not rows:
    fail("%s: no rows" % csv_path)
columns = list(rows[0].keys())
for c in ("step", "t", "cells"):
    if c not in columns:
        fail("%s: no column '%s'" % (csv_path, c))
interval = exodus_interval(info)
last = int(rows[-1]["step"])
out_rows = [r for r in rows if int(r["step"]) % interval == 0 or int(r["step"]) == last]
out_times = [float(r["t"]) for r in out_rows]
table_globals = [c for c in columns if c not in ("step", "t") and not c.startswith("time_")]

# ---------------------------------------------------------------------------------------------
# What ParaView shows.

if reader_kind == "legacy":
    reader = simple.ExodusIIReader(FileName=[exodus_path])
elif reader_kind == "ioss":
    reader = simple.IOSSReader(FileName=[exodus_path])
else:
    reader = simple.OpenDataFile(exodus_path)
    if reader is None:
        fail("%s: ParaView finds no reader for it" % exodus_path)
xml_name = reader.GetXMLName()
legacy = xml_name == "ExodusIIReader"
if not legacy and xml_name != "IOSSReader":
    fail("%s: ParaView opens it with %s, not an Exodus reader" % (exodus_path, xml_name))

if legacy:
    reader.SideSetArrayStatus = reader.SideSetArrayStatus.Available  # contact and the deck's boundary segments
    reader.SideSetResultArrayStatus = reader.SideSetResultArrayStatus.Available
    reader.PointVariables = reader.PointVariables.Available
    reader.ElementVariables = reader.ElementVariables.Available
    reader.GlobalVariables = reader.GlobalVariables.Available
    if "contact" not in reader.SideSetArrayStatus.Available and file_steps[0].side_keys is not None:
        fail("the reader lists no side set 'contact' (Side Sets: %s)" % list(reader.SideSetArrayStatus.Available))
else:
    side_sets = list(reader.GetProperty("SideSetInfo")[0::2]) if reader.GetProperty("SideSetInfo") else []
    if file_steps[0].side_keys is not None and "contact" not in side_sets:
        fail("the reader lists no side set 'contact' (Side Sets: %s)" % side_sets)
    reader.SideSets = side_sets
    reader.SideSetFields = list(reader.GetProperty("SideSetFieldInfo")[0::2])
    reader.NodeBlockFields = list(reader.GetProperty("NodeBlockFieldInfo")[0::2])
    reader.ElementBlockFields = list(reader.GetProperty("ElementBlockFieldInfo")[0::2])

pv_times = [float(t) for t in reader.TimestepValues]
files = list(dict.fromkeys(s.path for s in file_steps))
if len(pv_times) != len(out_rows) or len(file_steps) != len(out_rows):
    fail("ParaView shows %d time steps, the steps table has %d output steps (Exodus Interval %d), the %d files %d times"
         % (len(pv_times), len(out_rows), interval, len(files), len(file_steps)))
for i, (a, b, s) in enumerate(zip(pv_times, out_times, file_steps)):
    if not same(a, b) or not same(a, s.t):
        fail("time step %d: ParaView t = %s, steps table t = %s (step %s), file %s t = %s"
             % (i, fmt(a), fmt(b), out_rows[i]["step"], s.path, fmt(s.t)))


def arrays(attributes):
    return {attributes.GetAbstractArray(i).GetName(): attributes.GetAbstractArray(i)
            for i in range(attributes.GetNumberOfArrays()) if attributes.GetAbstractArray(i).GetName()}


def fetch(t):
    """The domain block, the blocks by name and the global field data at t."""
    reader.UpdatePipeline(t)
    out = reader.GetClientSideObject().GetOutputDataObject(0)
    blocks = {}
    if legacy:
        it = out.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            blocks.setdefault(it.GetCurrentMetaData().Get(out.NAME()), []).append(it.GetCurrentDataObject())
            it.GoToNextItem()
    else:
        for i in range(out.GetNumberOfPartitionedDataSets()):
            pds = out.GetPartitionedDataSet(i)
            name = out.GetMetaData(i).Get(out.NAME()) if out.HasMetaData(i) else None
            blocks[name] = [pds.GetPartition(j) for j in range(pds.GetNumberOfPartitions()) if pds.GetPartition(j)]
    for name, parts in blocks.items():
        if len(parts) > 1 or (not parts and name == "domain"):  # an empty side set comes in none
            fail("t = %s: block '%s' comes in %d pieces" % (fmt(t), name, len(parts)))
    if "domain" not in blocks:
        fail("t = %s: no element block 'domain' in ParaView's output (blocks: %s)" % (fmt(t), sorted(blocks)))
    domain = blocks["domain"][0]
    field = domain.GetFieldData() if legacy else out.GetFieldData()
    return domain, {name: parts[0] if parts else None for name, parts in blocks.items()}, arrays(field)


def check_side_block(where, name, block, keys_in_file, conn):
    """Checks that ParaView's block of side set `name` holds the file's (element, side) pairs and
    that its cells are boundary edges of the mesh (an edge beside hanging nodes counts too).
    Returns the order of the file's sides in the block's cells and the cells' lengths."""
    if block is None and not keys_in_file:  # an empty set: the IOSS reader gives its block no data
        return np.zeros(0, dtype=np.int64), np.zeros(0)
    if block is None:
        fail("%s: the side set '%s' is selected but ParaView shows no block '%s'" % (where, name, name))
    nsides = block.GetNumberOfCells()
    if nsides != len(keys_in_file):
        fail("%s: side set %s has %d cells in ParaView, %d sides in the file" % (where, name, nsides, len(keys_in_file)))
    scd = arrays(block.GetCellData())
    if legacy:
        keys = list(zip((vtk_to_numpy(scd["SourceElementId"]) + 1).tolist(), (vtk_to_numpy(scd["SourceElementSide"]) + 1).tolist()))
    else:
        keys = [tuple(k) for k in vtk_to_numpy(scd["element_side"]).tolist()]
    if sorted(keys) != sorted(keys_in_file):
        fail("%s: side set %s's (element, side) pairs in ParaView are not the file's" % (where, name))
    position = {k: j for j, k in enumerate(keys_in_file)}
    order = np.array([position[k] for k in keys], dtype=np.int64)
    spd = arrays(block.GetPointData())
    side_node = vtk_to_numpy(spd["GlobalNodeId" if legacy else "ids"]).astype(np.int64) - 1
    edges = {}
    if conn is not None:
        for quad in conn.tolist():
            for k in range(4):
                e = frozenset((quad[k] - 1, quad[(k + 1) % 4] - 1))
                edges[e] = edges.get(e, 0) + 1
    lengths = np.zeros(nsides)
    for j in range(nsides):
        cell = block.GetCell(j)
        if cell.GetNumberOfPoints() != 2:
            fail("%s: side set %s's cell %d has %d points, not 2" % (where, name, j, cell.GetNumberOfPoints()))
        p0, p1 = cell.GetPointId(0), cell.GetPointId(1)
        e = frozenset((int(side_node[p0]), int(side_node[p1])))
        if edges and edges.get(e) != 1:
            fail("%s: side set %s's edge %d (nodes %s) is not on the mesh's boundary" % (where, name, j, sorted(n + 1 for n in e)))
        q0, q1 = block.GetPoint(p0), block.GetPoint(p1)
        lengths[j] = math.hypot(q1[0] - q0[0], q1[1] - q0[1])
    return order, lengths


def vector_groups(names):
    """File variables u_x, u_y (, u_z) -> {'u': ['u_x', 'u_y']}; others alone."""
    groups = {}
    for n in names:
        m = re.match(r"^(.*)_([xyzXYZ])$", n)
        key = m.group(1) if m else n
        groups.setdefault(key, []).append(n)
    for key, members in list(groups.items()):
        if len(members) == 1 and members[0] != key:
            groups[members[0]] = members
            del groups[key]
    return groups


def tensor_groups(names):
    """File cell variables e_xx, e_yy, e_xy (exactly these three of a base e, the 2D symmetric tensor
    the IOSS reader shows as one array e) -> {'e': ['e_xx', 'e_yy', 'e_xy']}; others alone."""
    bases = {}
    for n in names:
        m = re.match(r"^(.*)_(xx|yy|zz|xy|yz|xz)$", n)
        if m:
            bases.setdefault(m.group(1), []).append(n)
    groups = {}
    for n in names:
        m = re.match(r"^(.*)_(xx|yy|zz|xy|yz|xz)$", n)
        base = m.group(1) if m else None
        if base is not None and [x.rsplit("_", 1)[1] for x in bases[base]] == ["xx", "yy", "xy"]:
            groups.setdefault(base, []).append(n)
        else:
            groups[n] = [n]
    return groups


def find_array(found, key, members, where):
    """The reader's array for a file variable (or group of components): (array, component names)."""
    candidates = [key] if len(members) == 1 else [key, key + "_"]
    for c in candidates:
        if c in found:
            a = found[c]
            if len(members) > 1 and a.GetNumberOfComponents() < len(members):
                fail("%s: '%s' has %d components, the file %d (%s)"
                     % (where, c, a.GetNumberOfComponents(), len(members), ",".join(members)))
            return a, c
    fail("%s: no array for the file's %s (arrays: %s)" % (where, ",".join(members), sorted(found)))


def compare(where, values, expected):
    if values.shape != expected.shape:
        fail("%s: %s values, the file has %s" % (where, values.shape, expected.shape))
    diff = values != expected
    if diff.any():
        i = int(np.flatnonzero(diff)[0])
        fail("%s: value %d is %s, the file says %s (%d differ)"
             % (where, i, fmt(values.flat[i]), fmt(expected.flat[i]), int(diff.sum())))


def global_value(found, name, where, s):
    """The value ParaView shows at s's time: IOSS gives one tuple, the legacy reader one per time of the file."""
    def pick(a):
        if a.GetNumberOfTuples() == 1:
            return 0
        if legacy and a.GetNumberOfTuples() == s.times_in_file:
            return s.k
        fail("%s: global '%s' has %d values in ParaView, the file %d times" % (where, a.GetName(), a.GetNumberOfTuples(), s.times_in_file))
    if name in found:
        a = found[name]
        if a.GetNumberOfComponents() == 1:
            return float(a.GetTuple1(pick(a)))
    m = re.match(r"^(.*?)(_?)([xyzXYZ])$", name)  # components glommed into a vector: probe:tip:x -> probe:tip:
    if m:
        for key in (m.group(1) + m.group(2), m.group(1)):
            if key in found and found[key].GetNumberOfComponents() >= 2:
                a = found[key]
                return float(a.GetComponent(pick(a), "xyz".index(m.group(3).lower())))
    fail("%s: no global variable '%s' (field data: %s)" % (where, name, sorted(found)))


nodal_groups = vector_groups(list(file_steps[0].nodal))
vector_names = []
adaptive = "eta" in columns
for c in table_globals:
    if c not in file_steps[0].globals:
        fail("%s: the steps table's column '%s' is no global variable of the file" % (file_steps[0].path, c))
extra = [g for g in file_steps[0].globals if g not in table_globals]
if extra:
    fail("%s: global variables %s are no columns of the steps table" % (file_steps[0].path, ",".join(extra)))
for want in ("u", "v", "a"):
    if want not in nodal_groups:
        fail("%s: no nodal variable %s (nodal: %s)" % (file_steps[0].path, want, list(file_steps[0].nodal)))
if "level" not in file_steps[0].cell:
    fail("%s: no cell variable level" % file_steps[0].path)
elastic = any(len(members) > 1 for members in nodal_groups.values())
for name in ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz", "von_mises", "eps_xx", "eps_yy", "eps_xy") if elastic else ():
    if name not in file_steps[0].cell:
        fail("%s: no cell variable %s in an elasticity run" % (file_steps[0].path, name))
if adaptive != ("indicator" in file_steps[0].cell):
    fail("%s: cell variable indicator %s in a%s run" % (file_steps[0].path, "missing" if adaptive else "present",
                                                        "n adaptive" if adaptive else " non-adaptive"))

meshes = set()
side_counts = set()
segment_sets = set()
for i, (t, s, row) in enumerate(zip(pv_times, file_steps, out_rows)):
    where = "t = %s (step %s, %s)" % (fmt(t), row["step"], os.path.basename(s.path))
    domain, blocks, field = fetch(t)
    npts, ncells = domain.GetNumberOfPoints(), domain.GetNumberOfCells()
    if npts != s.num_nodes or ncells != s.num_elem:
        fail("%s: ParaView shows %d points and %d cells, the file has %d and %d" % (where, npts, ncells, s.num_nodes, s.num_elem))
    if ncells != int(float(row["cells"])):
        fail("%s: ParaView shows %d cells, the steps table's cells is %s" % (where, ncells, row["cells"]))
    meshes.add((npts, ncells))
    pd, cd = arrays(domain.GetPointData()), arrays(domain.GetCellData())
    for n, arrs in (("GlobalNodeId" if legacy else "ids", pd), ("GlobalElementId" if legacy else "ids", cd)):
        if n not in arrs:
            fail("%s: the reader gives no id array '%s'" % (where, n))
    node_ids = vtk_to_numpy(pd["GlobalNodeId" if legacy else "ids"]).astype(np.int64) - 1  # 1-based in both readers
    cell_ids = vtk_to_numpy(cd["GlobalElementId" if legacy else "ids"]).astype(np.int64) - 1
    if sorted(node_ids.tolist()) != list(range(s.num_nodes)) or sorted(cell_ids.tolist()) != list(range(s.num_elem)):
        fail("%s: the reader's node or element ids are not 1..n" % where)
    pts = vtk_to_numpy(domain.GetPoints().GetData()).astype(float)
    tol = 1e-6 * max(1.0, float(np.abs(s.x).max()), float(np.abs(s.y).max()))  # the legacy reader has float points
    if np.abs(pts[:, 0] - s.x[node_ids]).max() > tol or np.abs(pts[:, 1] - s.y[node_ids]).max() > tol:
        fail("%s: ParaView's point coordinates are not the file's" % where)
    for key, members in nodal_groups.items():
        a, shown = find_array(pd, key, members, where)
        values = vtk_to_numpy(a).astype(float).reshape(npts, -1)
        for c, m in enumerate(members):
            compare("%s: nodal %s (ParaView '%s' component %d)" % (where, m, shown, c), values[:, c], s.nodal[m][node_ids])
        if len(members) > 1:
            if values.shape[1] > len(members) and np.any(values[:, len(members):] != 0):
                fail("%s: vector '%s' has non-zero extra components" % (where, shown))
            if i == 0:
                vector_names.append("%s(%d)" % (shown, values.shape[1]))
    for key, members in tensor_groups(list(s.cell)).items():
        if len(members) > 1 and key in cd:  # the IOSS reader's symmetric tensor (eps: xx, yy, xy)
            a, _ = find_array(cd, key, members, where)
            values = vtk_to_numpy(a).astype(float).reshape(len(cell_ids), -1)
            for c, name in enumerate(members):
                compare("%s: cell %s (ParaView '%s' component %d)" % (where, name, key, c), values[:, c],
                        s.cell[name][cell_ids])
            continue
        for name in members:
            a, _ = find_array(cd, name, [name], where)
            compare("%s: cell %s" % (where, name), vtk_to_numpy(a).astype(float), s.cell[name][cell_ids])
    for name in table_globals:
        shown = global_value(field, name, where, s)
        if not same(shown, s.globals[name]) or not same(shown, float(row[name])):
            fail("%s: global %s is %s in ParaView, %s in the file, %s in the steps table"
                 % (where, name, fmt(shown), fmt(s.globals[name]), row[name]))
    # The deck's boundary segments (supports, loads): side sets without variables.
    for name, keys_in_file in s.set_keys.items():
        if name != "contact":
            check_side_block(where, name, blocks.get(name), keys_in_file, s.conn)
            segment_sets.add(name)
    if s.side_keys is None:
        continue
    contact = blocks.get("contact")
    order, lengths = check_side_block(where, "contact", contact, s.side_keys, s.conn)
    side_counts.add(len(s.side_keys))
    scd = arrays(contact.GetCellData())
    for name, expected in s.side.items():
        a, _ = find_array(scd, name, [name], where + ", side set contact")
        compare("%s: side set contact %s" % (where, name), vtk_to_numpy(a).astype(float), expected[order])
    lam = vtk_to_numpy(find_array(scd, "lambda", ["lambda"], where)[0]).astype(float)
    gap = vtk_to_numpy(find_array(scd, "gap", ["gap"], where)[0]).astype(float)
    for label, value, column in (("min lambda", lam.min(), "min_lambda"), ("max lambda", lam.max(), "max_lambda"),
                                 ("min gap", gap.min(), "min_gap")):
        if column in row and not same(float(value), float(row[column])):
            fail("%s: %s on the side set is %s, the steps table's %s %s" % (where, label, fmt(value), column, row[column]))
    if "contact_force" in row:
        force, table = -float(np.dot(lam, lengths)), float(row["contact_force"])
        if abs(force - table) > 1e-6 * max(abs(table), float(np.abs(lam).max() * lengths.sum()), 1e-300):
            fail("%s: -sum lambda |E| on the side set is %s, the steps table's contact_force %s" % (where, fmt(force), row["contact_force"]))

# Filters > Data Analysis > Plot Global Variables Over Time.
plot = simple.PlotGlobalVariablesOverTime(Input=reader)
plot.UpdatePipeline()
table = plot.GetClientSideObject().GetOutputDataObject(0)
if not table.IsA("vtkTable"):
    fail("Plot Global Variables Over Time gives a %s, not a table" % table.GetClassName())
if table.GetNumberOfRows() != len(out_rows):
    fail("Plot Global Variables Over Time has %d rows, the steps table %d output steps" % (table.GetNumberOfRows(), len(out_rows)))
plot_columns = {table.GetColumnName(i): table.GetColumn(i) for i in range(table.GetNumberOfColumns())}
if "Time" not in plot_columns:
    fail("Plot Global Variables Over Time has no column Time (%s)" % sorted(plot_columns))
time_column = plot_columns["Time"]
for j, t in enumerate(out_times):
    if not same(float(time_column.GetValue(j)), t):
        fail("Plot Global Variables Over Time: row %d has Time %s, the steps table %s" % (j, fmt(time_column.GetValue(j)), fmt(t)))
for name in table_globals:
    m = re.match(r"^(.*?)(_?)([xyzXYZ])$", name)
    if name in plot_columns and plot_columns[name].GetNumberOfComponents() == 1:
        column, comp = plot_columns[name], 0
    elif m and (m.group(1) + m.group(2)) in plot_columns:
        column, comp = plot_columns[m.group(1) + m.group(2)], "xyz".index(m.group(3).lower())
    elif m and m.group(1) in plot_columns:
        column, comp = plot_columns[m.group(1)], "xyz".index(m.group(3).lower())
    else:
        fail("Plot Global Variables Over Time has no column for '%s' (%s)" % (name, sorted(plot_columns)))
    for j, row in enumerate(out_rows):
        value = float(column.GetComponent(j, comp))
        if not same(value, float(row[name])):
            fail("Plot Global Variables Over Time: %s at t = %s is %s, the steps table %s" % (name, row["t"], fmt(value), row[name]))

cells = sorted(c for _, c in meshes)
print("check_paraview: OK: %s: %s reader, %d time steps t = %s..%s from %d file(s) (Exodus Interval %d), "
      "%d distinct mesh size(s), %s..%s cells; nodal %s%s; cell %s; %s%s; "
      "%d global variables over time" % (
          exodus_path, "legacy ExodusII" if legacy else "IOSS", len(pv_times), fmt(pv_times[0]), fmt(pv_times[-1]),
          len(files), interval, len(meshes), cells[0], cells[-1], ",".join(nodal_groups),
          " (vectors " + ",".join(vector_names) + ")" if vector_names else "", ",".join(file_steps[0].cell),
          ("side set contact (%s..%s sides) with %s" % (min(side_counts), max(side_counts), ",".join(file_steps[0].side)))
          if side_counts else "no side set contact (no contact boundary)",
          ", side sets " + ",".join(sorted(segment_sets)) if segment_sets else "", len(table_globals)))
