"""Elastic moduli C22 and C33 of a 2D packing between two walls from the
linear response of its contact network (paper 003 Table II), an independent
check of the DEM measurement of examples/sound/in.moduli.

The network is the one fix acoustic/mindlin exposes (its local array: atom
IDs i and j, 0 for a wall, normal force f_n and normal stiffness k_n): each
contact is a normal spring k_n and a tangential spring k_t = eta k_n at the
contact point (Hertz-Mindlin, eta = 2 (1 - nu) / (2 - nu), 1 for nu = 0),
on grains that translate in the xy plane and rotate about z.  The bottom
wall is clamped; the top wall is displaced by -eps h along y (C22 = the
change of the force per unit area on the top wall over eps) or by gamma h
along x (C33 = the change of the shear force per unit area over gamma), the
grains take the positions of least elastic energy, K u = f.  The box is
periodic along x with length `width`; the 2D layer counts as one diameter
(unit) thick, as in paper 003.  The prestress (geometric) term f_n / r of
the stiffness is left out: it is of relative size overlap / radius, 1e-3 at
p = 1e-4.  model "normal" is the frictionless network of a packing made
with mu = 0 (in.measure's model normal): normal springs only, on the
grains' translations (no tangential spring, no rotation); its C33 is zero,
since flat frictionless walls carry no shear force.  numpy and scipy only."""
import numpy as np
import scipy.sparse
import scipy.sparse.linalg


def _contact_geometry(grains, contacts, width, height):
    """normals (from i to j, or to the wall) and lever arms of every contact,
    with the index of each grain and the wall (0: bottom, 1: top) of the
    grain-wall contacts"""
    index = {int(t): k for k, t in enumerate(grains["id"])}
    x, y, radius = grains["x"], grains["y"], grains["radius"]
    ci = np.array([index[int(t)] for t in contacts[0]])
    wall = contacts[1].astype(int) == 0
    cj = np.array([index.get(int(t), -1) for t in contacts[1]])
    normal = np.zeros((len(ci), 2))
    arm_j = np.zeros(len(ci))
    grain = ~wall
    dx = x[cj[grain]] - x[ci[grain]]
    dx -= width * np.round(dx / width)    # periodic along x
    dy = y[cj[grain]] - y[ci[grain]]
    length = np.hypot(dx, dy)
    normal[grain, 0], normal[grain, 1] = dx / length, dy / length
    arm_j[grain] = radius[cj[grain]]
    top = wall & (y[ci] > 0.5 * height)
    normal[wall, 1] = np.where(top[wall], 1.0, -1.0)
    which_wall = np.where(top, 1, 0)
    return ci, cj, wall, which_wall, normal, radius[ci], arm_j


MODELS = ("full", "normal")


def compatibility(grains, contacts, width, height, eta=1.0, model="full"):
    """The linear network of a 2D packing between two walls (bottom y = 0,
    top y = height): the compatibility matrix B (2 rows per contact: the
    normal and tangential relative displacement of the contact point, j
    minus i, or the wall minus i, for the 3 DOFs x, y, theta of each grain
    in the order of grains["id"]), the springs (k_n, eta k_n per contact,
    in the order of B's rows), and the geometry of _contact_geometry as a
    dict: normal, tangent, wall (bool), which_wall (0 bottom, 1 top) per
    contact.  A wall's motion w enters a contact's rows as (w.n, w.t).
    model "normal": the frictionless network, 2 DOFs x, y per grain and
    the tangential springs zero (the rows stay two per contact)."""
    if model not in MODELS:
        raise ValueError(f"model {model!r}: one of {MODELS}")
    ci, cj, wall, which_wall, normal, arm_i, arm_j = _contact_geometry(grains, contacts, width, height)
    kn = np.asarray(contacts[3], dtype=float)
    tangent = np.column_stack((-normal[:, 1], normal[:, 0]))
    ngrains = len(grains["id"])
    ncontacts = len(ci)
    # rows: the normal and tangential relative displacements of each contact,
    # s = B u + s_wall (j minus i at the contact point; rotation theta about z
    # moves the contact point of i by r_i theta t and that of j by -r_j theta t)
    rows, cols, vals = [], [], []
    for c in range(ncontacts):
        n, t = normal[c], tangent[c]
        i = ci[c]
        for r, direction in ((2 * c, n), (2 * c + 1, t)):
            rows += [r, r]
            cols += [3 * i, 3 * i + 1]
            vals += [-direction[0], -direction[1]]
        rows.append(2 * c + 1)
        cols.append(3 * i + 2)
        vals.append(-arm_i[c])
        if wall[c]:
            continue
        j = cj[c]
        for r, direction in ((2 * c, n), (2 * c + 1, t)):
            rows += [r, r]
            cols += [3 * j, 3 * j + 1]
            vals += [direction[0], direction[1]]
        rows.append(2 * c + 1)
        cols.append(3 * j + 2)
        vals.append(-arm_j[c])
    B = scipy.sparse.csr_matrix((vals, (rows, cols)), shape=(2 * ncontacts, 3 * ngrains))
    springs = np.empty(2 * ncontacts)
    springs[0::2], springs[1::2] = kn, eta * kn
    if model == "normal":
        translations = np.arange(3 * ngrains) % 3 != 2
        B = B[:, np.flatnonzero(translations)]
        springs[1::2] = 0.0
    return B, springs, {"normal": normal, "tangent": tangent, "wall": wall, "which_wall": which_wall}


def wall_stretch(geometry, motions):
    """the wall part of the contacts' relative displacements (2 per contact,
    as B's rows) when the walls move: motions = {0: (ux, uy) of the bottom
    wall, 1: (ux, uy) of the top wall}"""
    normal, tangent = geometry["normal"], geometry["tangent"]
    prescribed = np.zeros(2 * len(normal))
    for which, motion in motions.items():
        chosen = geometry["wall"] & (geometry["which_wall"] == which)
        motion = np.asarray(motion, dtype=float)
        prescribed[0::2][chosen] = normal[chosen] @ motion
        prescribed[1::2][chosen] = tangent[chosen] @ motion
    return prescribed


def wall_force(geometry, springs, stretch, which=1):
    """the force (x, y) of the grains on one wall (0 bottom, 1 top) from the
    contacts' relative displacements (stretch, as B's rows):
    -(k_n s_n n + k_t s_t t) summed over that wall's contacts"""
    normal, tangent = geometry["normal"], geometry["tangent"]
    on = geometry["wall"] & (geometry["which_wall"] == which)
    force = -(springs[0::2][on, None] * stretch[0::2][on, None] * normal[on]
              + springs[1::2][on, None] * stretch[1::2][on, None] * tangent[on])
    return force.sum(axis=0)


def regularised(K):
    """K plus a tiny multiple of the identity: grains without stiffness
    (rattlers) and floppy directions stay unloaded instead of making K
    singular"""
    diagonal = K.diagonal()
    scale = np.median(diagonal[diagonal > 0]) if np.any(diagonal > 0) else 1.0
    return (K + scipy.sparse.identity(K.shape[0], format="csc") * (1e-12 * scale)).tocsc()


def network_response(grains, contacts, width, height, wall_motion, eta=1.0, model="full"):
    """the force (x, y) of the grains on the top wall per unit area after the
    top wall moved by wall_motion = (ux, uy), the bottom wall and the
    periodic box staying put; grains: dict with id, x, y, radius; contacts:
    the columns of fix acoustic/mindlin's local array by position
    (0: i, 1: j, 0 for a wall, 3: k_n; a lammps_output.Snapshot); model:
    "full" or "normal" (frictionless, compatibility)"""
    B, springs, geometry = compatibility(grains, contacts, width, height, eta, model)
    prescribed = wall_stretch(geometry, {1: wall_motion})
    K = (B.T @ scipy.sparse.diags(springs) @ B).tocsc()
    load = -(B.T @ (springs * prescribed))
    u = scipy.sparse.linalg.spsolve(regularised(K), load)
    stretch = B @ u + prescribed
    return wall_force(geometry, springs, stretch) / width


def network_moduli(grains, contacts, width, height, eta=1.0, strain=1e-6, model="full"):
    """C22 (top wall pushed down by strain * height) and C33 (top wall slid
    by strain * height along x) of the network; linear, so any small strain
    gives the same moduli.  model "normal": the frictionless network (C33
    zero: no tangential spring at the walls)"""
    push = network_response(grains, contacts, width, height, (0.0, -strain * height), eta, model)
    slide = network_response(grains, contacts, width, height, (strain * height, 0.0), eta, model)
    return {"C22": float(push[1] / strain), "C33": float(-slide[0] / strain)}
