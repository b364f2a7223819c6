"""The start of the Python tests' decks: a 2D hexagonal layer of equal
grains (type 1, diameter 1.002, slightly overlapping) on a row of base
grains (type 2), periodic along x, in LJ units."""


def hex_layer(width, height, top):
    """`width` lattice spacings wide, a box `height` high, grains up to `top`;
    groups base (type 2) and grains (type 1)"""
    return f"""
units lj
dimension 2
atom_style sphere
boundary p fm p
comm_modify vel yes
lattice hex 1.1547005383792517
region box block 0 {width} 0 {height} -0.5 0.5
create_box 2 box
region base block INF INF -0.1 0.1 INF INF units box
region layer block INF INF 0.5 {top} INF INF units box
create_atoms 2 region base
create_atoms 1 region layer
group base type 2
group grains type 1
set group all diameter 1.002
set group all density 1.0
"""
