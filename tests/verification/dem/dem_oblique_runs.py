"""Oblique drop tests of a `corlab dem --friction` export in the three real codes (Debian's
LAMMPS, LIGGGHTS and YADE, never mocked): one sphere of type 1 hits the export's wall (the plane
z = 0) at speed v [m/s] and angle theta [deg] from the normal, without gravity, at the export's
own time step. Each code runs every angle in one process and prints per angle the rebound
velocity (vx, vz) [m/s] and spin omega_y [rad/s]; positive omega_y is the rolling sense of the
incident motion (+x), the convention of data/kharaz2001. Used by dem_oblique_check.py."""
# SPDX-License-Identifier: BSD-3-Clause
import math
import os

from dem_check_common import contact_time, run


class Case:
    """The sphere of the export's 1-wall pair at speed v [m/s], angle theta [deg], step dt [s]:
    it starts 20 normal steps above the wall and runs until 2 contact times after touching."""

    def __init__(self, data, theta, v, dt):
        pair = {p["pair"]: p for p in data["pairs"]}["1-wall"]
        self.theta, self.v, self.dt = theta, v, dt
        self.radius = data["types"][0]["radius_m"]
        self.density = data["types"][0]["density_kg_per_m3"]
        self.vn = v * math.cos(math.radians(theta))
        self.vt = v * math.sin(math.radians(theta))
        self.gap = 20.0 * self.vn * dt
        self.steps = int((self.gap / self.vn + 2.0 * contact_time(pair, self.vn)) / dt)
        self.ntypes = len(data["types"])


def parse_rows(out):
    """{theta: (vx, vz, omega_y[, kno, kso])} from the CORLAB_ROW lines of a code's output."""
    rows = {}
    for line in out.splitlines():
        if line.startswith("CORLAB_ROW"):
            values = [float(x) for x in line.split()[1:]]
            rows[values[0]] = tuple(values[1:])
    return rows


def lammps_block(fragment, case):
    r = case.radius
    return ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block -%g %g -%g %g -%g %g" % ((8 * r,) * 6),
            "create_box %d box" % case.ntypes,
            "create_atoms 1 single 0 0 %.12g" % (r + case.gap),
            "set atom 1 diameter %.12g density %.12g" % (2 * r, case.density),
            "velocity all set %.12g 0 %.12g" % (case.vt, -case.vn),
            "include %s" % fragment]


def liggghts_block(fragment, case):
    r = case.radius
    return ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
            "communicate single vel yes", "units si", "hard_particles yes",
            "region reg block -%g %g -%g %g -%g %g units box" % ((8 * r,) * 4 + (0.001 * r, 8 * r)),
            "create_box %d reg" % (case.ntypes + 1), "include %s" % fragment,
            "create_atoms 1 single 0 0 %.12g units box" % (r + case.gap),
            "set atom 1 diameter %.12g density %.12g" % (2 * r, case.density),
            "velocity all set %.12g 0 %.12g units box" % (case.vt, -case.vn)]


def lammps_like_input(block, fragment, cases):
    """One input running every case in turn (`clear` between them); LAMMPS and LIGGGHTS."""
    lines = []
    for case in cases:
        lines += block(fragment, case)
        lines += ["fix corlab_nve all nve/sphere", "timestep %.12g" % case.dt,
                  "compute corlab_w all property/atom omegay",
                  "compute corlab_wsum all reduce sum c_corlab_w",
                  "thermo_style custom step c_corlab_wsum", "thermo 0",
                  "run %d" % case.steps,
                  "variable corlab_vx equal vx[1]", "variable corlab_vz equal vz[1]",
                  "variable corlab_w equal c_corlab_wsum",
                  'print "CORLAB_ROW %.6f ${corlab_vx} ${corlab_vz} ${corlab_w}"' % case.theta,
                  "clear"]
    return "\n".join(lines) + "\n"


def run_lammps(lmp, out, cases):
    path = os.path.join(out, "in.oblique_lammps")
    with open(path, "w") as f:
        f.write(lammps_like_input(lammps_block, os.path.join(out, "lammps.in"), cases))
    return parse_rows(run([lmp, "-in", path, "-log", "none", "-echo", "none"], cwd=out).stdout)


def run_liggghts(liggghts, out, cases):
    path = os.path.join(out, "in.oblique_liggghts")
    with open(path, "w") as f:
        f.write(lammps_like_input(liggghts_block, os.path.join(out, "liggghts.in"), cases))
    return parse_rows(run([liggghts, "-in", path, "-log", "none", "-echo", "none"],
                          cwd=out).stdout)


YADE_CASE = """
O.reset()
exec(open(%(fragment)r).read())
R = %(radius).17g
for w in corlab_walls:  # a Box, as this table was measured: YADE's Wall applies F_t at R - delta
    O.bodies.erase(w)
w = O.bodies.append(box((0, 0, -R), (8 * R, 8 * R, R), fixed=True, material=corlab_wall_mat))
a = O.bodies.append(sphere((0, 0, R + %(gap).17g), R, material=corlab_mat1))
O.bodies[a].state.vel = Vector3(%(vt).17g, 0, %(vn).17g)
O.engines = [ForceResetter(), InsertionSortCollider(corlab_bound),
             InteractionLoop(corlab_ig2, [corlab_ip2], [corlab_law2]),
             NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]
O.dt = %(dt).17g
O.run(%(touch)d, True)
k = (O.interactions[w, a].phys.kno, O.interactions[w, a].phys.kso) \\
    if O.interactions.has(w, a) and O.interactions[w, a].isReal else (0.0, 0.0)
O.run(%(rest)d, True)
s = O.bodies[a].state
print('CORLAB_ROW %(theta).6f', s.vel[0], s.vel[2], s.angVel[1], k[0], k[1])
"""


def run_yade(yade, out, cases):
    """YADE: also reads the contact's kno [N/m^1.5] and kso [N/m^1.5] a few steps after touch
    (on a Box in place of the fragment's floor)."""
    text = ""
    for case in cases:
        touch = int(case.gap / case.vn / case.dt) + 5
        text += YADE_CASE % {"fragment": os.path.join(out, "yade_fragment.py"),
                             "radius": case.radius, "gap": case.gap, "vt": case.vt,
                             "vn": -case.vn, "dt": case.dt, "touch": touch,
                             "rest": case.steps - touch, "theta": case.theta}
    path = os.path.join(out, "oblique_yade.py")
    with open(path, "w") as f:
        f.write(text)
    return parse_rows(run([yade, "-n", "-x", path], cwd=out).stdout)
