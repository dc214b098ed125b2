"""The gallery: every figure femgear draws, made from the zoo scenes by femgear's own commands.

One entry of :data:`FIGURES` is one figure: its name (the file ``docs/gallery/<name>.png``), the group of the
page it belongs to, the command a user types to get it, the file of that command's output folder that is the
figure (or a ParaView set :mod:`render` draws), the code that draws it (``path::function``: what the staleness
check reads) and two lines on what to read in it.  The page ``gallery.md`` is generated from this table at
build time (``docs/gen/pages.py``), and a Markdown page shows any entry with the line
``<!-- figure: NAME -->`` (``docs/gen/hooks.py``), so a command is written once.

The pictures are committed (together about 1.6 MB): making them all runs femgear for about 2.7 minutes of CPU,
4-5 minutes of wall time on two shared cores (258 s measured), too long for the docs build of ``make test``;
the stale ones alone take the time of their commands (10-50 s each).  Each carries a digest of its inputs
in ``docs/gallery/manifest.json``: the entry (command, output, rendering), the scene files the command reads
(parsed, so a comment does not count), and the code that draws and writes it (the named functions and the
module-level helpers they use, parsed without docstrings).  ``tests/docs/test_gallery.py`` fails when a
digest is not the current one.  What the digest leaves out is the physics under the figure: a change of
femgear's numbers shows in the pictures only after ``make gallery``.

    python docs/gen/gallery.py              # regenerate the stale and missing figures (``make docs`` runs it)
    python docs/gen/gallery.py --all        # every figure (``make gallery``)
    python docs/gen/gallery.py --only A,B   # these figures
    python docs/gen/gallery.py --check      # list the stale figures; exit 1 if any (computes nothing)
    python docs/gen/gallery.py --list       # the commands, one per line
"""

from __future__ import annotations

import argparse
import ast
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
import tomllib
from dataclasses import asdict, dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GALLERY = ROOT / "docs" / "gallery"
MANIFEST = GALLERY / "manifest.json"
WORK = ROOT / "out" / "gallery"
#: the matplotlib figures as committed: a palette of this many colours, at their own resolution (120 dpi); the
#: rendered views keep every colour (a palette bands their shading and colour bar)
COLOURS = 128


@dataclass(frozen=True)
class Render:
    """A picture of a ParaView set of the command's output (:func:`render.render_flank`)."""

    field: str            #: point field coloured
    scale: float          #: factor on the field (1e-6: Pa to MPa)
    label: str            #: colour-bar title, with the unit
    part: int = 0         #: dataset of the .pvd (0: the pinion)
    title: str = ""       #: text at the top left


@dataclass(frozen=True)
class Figure:
    """One figure of the gallery."""

    name: str                 #: ``docs/gallery/<name>.png``
    group: str                #: a key of :data:`GROUPS`
    title: str                #: the heading on the page
    command: str              #: the command line as a user types it (the gallery adds ``-q`` and ``--out``)
    output: str               #: the file in the command's output folder: the PNG, or the ``.pvd`` to render
    code: tuple[str, ...]     #: ``path::function`` of the code that draws and writes it
    read: tuple[str, str]     #: two lines: what to read in it
    render: Render | None = None


#: the page's sections in the order a user meets them: key -> (heading, one paragraph)
GROUPS: dict[str, tuple[str, str]] = {
    "run": ("A first run: `femgear run`",
            "`femgear run SCENE` computes the scene's physics and writes these figures with `results.json` "
            "(the files: [the files of a run](guide/outputs.md))."),
    "wear": ("Wear and the coupled fields along the path",
             "With `wear.cycles` above zero the run wears the flanks before the last pass; the coupled fields "
             "figure shows what the loop converged to."),
    "dynamics": ("Vibration: `femgear dynamics`",
                 "One dynamic run at the scene's speed (the same four figures come with `femgear run` when "
                 "`physics.dynamics` is on). How to read them: [Reading the vibration outputs](guide/vibration.md)."),
    "speed": ("Against speed: `femgear dynamics --sweep`, `--campbell`, `--runup`",
              "The order sweep (harmonic balance per speed, time integration where the flanks separate) with the "
              "natural frequencies marked, the dynamic factor K_v from femgear's dynamics beside ISO 6336-1 method "
              "B, the Campbell diagram, and a run-up tracked by order ([whine per order](models/whine.md))."),
    "housing": ("The housing: `[housing]` in a run",
                "With a `[housing]` table the run adds the path from the bearings to sensors on a gearbox housing and "
                "to the air ([the housing model](models/housing.md)); here the parametric FE housing around the "
                "baseline pair, swept over speed."),
    "ltca": ("Loaded tooth contact: `femgear ltca`",
             "The loaded tooth contact analysis on the 3-D member bodies alone ([the ltca tool](ltca_tool.md)), "
             "here with a linear tip relief of 10 µm over 2.5 mm on both members."),
    "ehl": ("One contact's lubricant film: `femgear ehl`",
            "The finite-element EHL solver in Moes' dimensionless groups, at the pitch point of a zoo pair "
            "(M and L from `femgear info SCENE`)."),
    "sweep": ("Many load cases: `femgear sweep`",
              "A grid of load cases of one base scene ([Sweeps](guide/sweeps.md)); `summary.png` draws the "
              "chosen outputs against the swept keys."),
}

BASE = "studies/zoo/paper_baseline.toml"
MARINE = "studies/zoo/marine.toml"
RUN = f"femgear run {BASE}"
WORN = f"femgear run {BASE} --set wear.cycles=1e6 --set 'physics.preset=\"fast\"'"
DYN, DYN_M = f"femgear dynamics {BASE}", f"femgear dynamics {MARINE}"
SPEED, SPEED_M = f"femgear dynamics {BASE} --sweep 1000:9500:35", f"femgear dynamics {MARINE} --sweep 300:4500:22"
CAMPBELL, CAMPBELL_M = f"{DYN} --campbell 0:12000:61", f"{DYN_M} --campbell 0:4500:46"
RUNUP = f"{DYN} --runup 800:2000:2"
KS = f"{DYN} --kahraman-singh"
HOUSING = (f"{RUN} --set 'housing.model=\"fe\"' --set 'housing.speed_range=[500,9000]' --set housing.orders=3 "
           "--no-vtk")
LTCA = (f"femgear ltca {BASE} --set modifications.tip_relief=10e-6 --set modifications.tip_relief_length=2.5e-3 "
        "--torques 100,200,300 --harris")

P, IO, CLI = "femgear/edge/plot/", "femgear/edge/io/", "femgear/edge/cli/"
RUN_FIG, DYN_FIG = IO + "run.py::_figures", IO + "dynamics.py::write_dynamics"
SWEEP_FIG = (IO + "nvh.py::write_order_sweep", CLI + "dynamics_nvh.py::run_sweep")
LTCA_FIG = CLI + "ltca.py::_write"
CAMPBELL_FIG = (P + "campbell.py::plot_campbell", IO + "campbell.py::write_campbell", CLI + "campbell.py::run_campbell")
RUNUP_FIG = (P + "nvh.py::plot_runup", IO + "nvh.py::write_runup", CLI + "dynamics_nvh.py::run_runup")
MPA = 1e-6

FIGURES: tuple[Figure, ...] = (
    # ---- a first run
    Figure("baseline_contact_path", "run", "Contact along the path: Hertz pressure, film, speeds", RUN,
           "contact_path.png", (P + "path.py::plot_contact_path", RUN_FIG),
           ("The Hertz pressure is largest near the pitch point (0) and falls towards both ends of the path, "
            "where the contact lines carry less load per length; the films change by a few per cent only.",
            "Sliding changes sign at the pitch point (pure rolling there, approach on the left), while the "
            "entrainment speed that builds the film stays almost constant.")),
    Figure("baseline_friction_path", "run", "Friction and contact temperature along the path", RUN,
           "friction_path.png", (P + "path.py::plot_friction_path", RUN_FIG),
           ("μ drops to zero at the pitch point, where sliding vanishes, and levels off at 0.03–0.035 towards "
            "both ends of the path.",
            "The oil's temperature rise follows the frictional heating (friction force times sliding speed): "
            "largest at the start and end of contact, zero at the pitch point.")),
    Figure("baseline_rating_path", "run", "ISO/TS 6336-20/22 scuffing and micropitting along the path", RUN,
           "rating_path.png", (P + "rating.py::plot_rating_path", RUN_FIG),
           ("Top: ISO's contact temperature θ_B stays far below the scuffing temperature θ_S (the safety S_B is "
            "in the legend); femgear's own contact temperature runs just below ISO's.",
            "Bottom: the specific film thickness λ, ISO/TS 6336-22's and femgear's h_min/R_a, far above the "
            "permissible λ_GFP: the micropitting safety S_λ is their ratio.")),
    Figure("baseline_convergence", "run", "Convergence of the coupling loop", RUN,
           "convergence.png", (P + "coupled.py::plot_convergence", RUN_FIG),
           ("Each coupling pass reruns the dynamics and the lubrication with the other's last result; the "
            "changes fall by a factor of 10–35 a pass: the loop contracts fast.",
            "The run stops at the first pass below the tolerance (dotted); a loop that levels off above it "
            "stops with a convergence error carrying this history.")),
    Figure("baseline_flanks_pressure", "run", "ParaView: the Hertz pressure on the pinion's flank", RUN,
           "flanks.pvd", (IO + "paraview_run.py::write_run_paraview",),
           ("The pinion's active flank, both helices meeting at the apex, its tip at the top, seen from the "
            "mating flank (`flanks.pvd` rendered off-screen with pyvista).",
            "The path model's pressure (the first figure's) varies along the profile only: highest in a band "
            "just below the pitch line, lowest at the tip, the same across the face width."),
           render=Render("hertz_pressure", MPA, "Hertz pressure [MPa]", title="pinion flank, both helices")),
    # ---- wear
    Figure("baseline_worn_tribology_path", "wear", "Load, friction, thermal deviation and wear after 10⁶ cycles",
           WORN, "tribology_path.png", (P + "coupled.py::plot_coupled_path", RUN_FIG),
           ("Each member wears most on its own dedendum, where its specific sliding is largest: the pinion at the "
            "start of contact (left), the gear at the end (right); nothing wears at the pitch point.",
            "The worn profiles concentrate the load at the pitch line: 225 N/mm there against 92 N/mm on the new "
            "flanks (the run above), which is where pitting starts.")),
    # ---- dynamics at the scene's speed
    Figure("baseline_dynamics_mesh_force", "dynamics", "Dynamic mesh force per helix (baseline)", DYN,
           "dynamics_mesh_force.png", (P + "dynamics.py::plot_mesh_force", DYN_FIG),
           ("The mesh force of each helix swings by about ±0.4 % about its static share, in a pattern repeating "
            "every mesh period, with bursts of ringing at much higher frequency.",
            "Stagger 0: both helices mesh in phase and carry equal forces, so their difference (bottom) is "
            "round-off; a staggered pair shows its helices' out-of-phase parts there.")),
    Figure("marine_dynamics_mesh_force", "dynamics", "Dynamic mesh force per helix (marine)", DYN_M,
           "dynamics_mesh_force.png", (P + "dynamics.py::plot_mesh_force", DYN_FIG),
           ("A 3 MW pair: 146 kN per helix, swinging by about ±1 % in a pattern that repeats every mesh period.",
            "The swing is smooth, a few mesh harmonics without the baseline's high-frequency ringing: its "
            "journal bearings damp 5 × 10⁵ N s/m against the baseline's 3.4 × 10³.")),
    Figure("baseline_dynamics_spectra", "dynamics", "Spectra of the DTE and of a bearing acceleration (baseline)",
           DYN, "dynamics_spectra.png", (P + "dynamics.py::plot_spectra", DYN_FIG),
           ("The dynamic transmission error (top) is mostly mesh order 1 and its first harmonics: the "
            "stiffness ripple's excitation.",
            "The bearing acceleration (bottom) peaks at high orders, where a mesh harmonic comes near a natural "
            "frequency (`--modes`): orders 9–12 around the 2.85 kHz torsional mode (order 11.0), 31–32 around "
            "the 8.1 and 8.3 kHz modes.")),
    Figure("marine_dynamics_spectra", "dynamics", "Spectra of the DTE and of a bearing acceleration (marine)",
           DYN_M, "dynamics_spectra.png", (P + "dynamics.py::plot_spectra", DYN_FIG),
           ("The DTE is mesh order 1 and its harmonics 2–4; above order 5 almost nothing.",
            "The bearing acceleration is largest at order 4: 4 × 580 Hz = 2.32 kHz lies just below the 2.41 kHz "
            "torsional mode, which holds 92 % of its strain energy in the mesh.")),
    Figure("baseline_dynamics_bearings", "dynamics", "Bearing loads (baseline)", DYN,
           "dynamics_bearings.png", (P + "dynamics.py::plot_bearing_forces", DYN_FIG),
           ("The load of the shafts on their four bearings about its mean (top) and its spectrum (bottom); the "
            "legends' means, 782 N along x and 1858 N along y (2015 N radial), are the static mesh forces shared "
            "by each shaft's two bearings.",
            "The swing is 10–11 N peak-to-peak, 0.5 % of the mean, left and right alike (stagger 0): mesh orders "
            "1–2 from the stiffness ripple, and orders 7–12 raised by the 2.85 kHz torsional mode (order 11.0), "
            "as in the acceleration's spectrum.")),
    Figure("marine_dynamics_bearings", "dynamics", "Bearing loads (marine)", DYN_M,
           "dynamics_bearings.png", (P + "dynamics.py::plot_bearing_forces", DYN_FIG),
           ("129 kN radial on each bearing (50.2 kN along x, 118.6 kN along y); the pinion's bearings swing by "
            "1.73 kN peak-to-peak along y (1.3 % of the mean), the gear's by 1.07 kN.",
            "The pinion's bearings carry mesh orders 1–4 about equally, order 4 raised by the 2.41 kHz torsional "
            "mode (4 × 580 Hz = 2.32 kHz); the gear's bearings mostly order 1.")),
    Figure("baseline_dynamics_time", "dynamics", "Lateral motion of the pinion and gear centres", DYN,
           "dynamics_time.png", (P + "dynamics.py::plot_time_histories", DYN_FIG),
           ("Displacement and velocity of each member's centre about their means over five mesh periods: "
            "hundredths of a micrometre, in a pattern repeating every mesh period.",
            "Velocity weights each frequency by 2π f: the ringing that hardly shows in the displacements "
            "dominates the velocities.")),
    Figure("baseline_dynamics_phase", "dynamics", "Phase planes of the pinion and gear centres", DYN,
           "dynamics_phase.png", (P + "dynamics.py::plot_phase_planes", DYN_FIG),
           ("Velocity against displacement over ten mesh periods: the steady periodic response retraces one "
            "closed orbit every mesh period, so the ten lie on top of each other.",
            "The loops and spirals in it are the higher harmonics and the ringing; a sub-harmonic or chaotic "
            "response (after contact loss) would close only after several periods or fill the plane.")),
    Figure("kahraman_singh", "dynamics", "The backlash oscillator of Kahraman and Singh",
           KS, "kahraman_singh.png",
           (P + "dynamics.py::plot_branches", CLI + "dynamics_nvh.py::run_kahraman_singh"),
           ("The one-degree-of-freedom mesh with backlash, swept up and down in frequency: between Ω ≈ 0.8 and "
            "0.92 two steady amplitudes coexist, a softening resonance.",
            "The up sweep jumps up at 0.92, the down sweep falls just below 0.8; on the upper branch the teeth "
            "separate for 35–47 % of each period (the check of femgear's nonlinear mesh).")),
    Figure("kahraman_singh_hb", "dynamics", "The backlash oscillator by harmonic balance: through the folds", KS,
           "kahraman_singh_hb.png", (P + "nvh.py::plot_ks_continuation", CLI + "dynamics_nvh.py::run_kahraman_singh"),
           ("The same oscillator by harmonic balance, continued through both folds (dotted, at Ω = 0.800 and "
            "0.909): stable branches solid, the unstable middle branch dashed; the swept time integrations "
            "(markers) lie on the stable ones.",
            "Between the folds three periodic solutions coexist: the up sweep stays on the lower branch up to the "
            "fold at 0.909, the down sweep on the upper one down to 0.800; the jumps of the swept figure are "
            "these folds.")),
    # ---- against speed
    Figure("baseline_dynamics_sweep", "speed", "DTE against speed (baseline)", SPEED,
           "dynamics_sweep.png", (P + "dynamics.py::plot_sweep", *SWEEP_FIG),
           ("The DTE RMS peaks where the mesh frequency or one of its harmonics meets a mode with mesh strain "
            "energy (dashed: f_m = f_n; dotted: f_m = f_n / k); the largest, at 8000 rpm, is the 2nd harmonic "
            "meeting the 8.1 and 8.3 kHz modes.",
            "Near f_m = 2.7–2.85 kHz the 2.85 kHz torsional mode and the 3rd harmonic of the 8.1/8.3 kHz modes "
            "meet; just above it the DTE falls to its lowest.")),
    Figure("marine_dynamics_sweep", "speed", "DTE against speed (marine)", SPEED_M,
           "dynamics_sweep.png", (P + "dynamics.py::plot_sweep", *SWEEP_FIG),
           ("Many crossings are marked, yet the DTE RMS rises smoothly: none raises a peak, unlike on the "
            "baseline, whose bearings damp about 150 times less.",
            "It steepens towards the 2.41 kHz torsional mode (92 % mesh energy), whose crossing f_m = f_n lies "
            "at about 5000 rpm, beyond this sweep.")),
    Figure("baseline_dynamics_orders", "speed", "Whine per mesh order against speed (baseline)", SPEED,
           "dynamics_orders.png", (P + "nvh.py::plot_order_sweep", *SWEEP_FIG),
           ("Each mesh order's amplitude of the dynamic mesh force (top) and of the largest radial bearing load "
            "(bottom) against speed, by harmonic balance at every speed (no × marks: the flanks never separate); "
            "dotted: f_n / k.",
            "Each order peaks where it meets a mode with mesh energy: order 1 at 5500 rpm (80 N, 2.85 kHz), order "
            "4 at 4000 rpm (78 N, 8.1/8.3 kHz), order 2 at 8250 rpm (141 N); the bearings feel order 1 most (143 "
            "N at 5500 rpm).")),
    Figure("marine_dynamics_orders", "speed", "Whine per mesh order against speed (marine)", SPEED_M,
           "dynamics_orders.png", (P + "nvh.py::plot_order_sweep", *SWEEP_FIG),
           ("Order 1 grows towards the 2.41 kHz torsional mode beyond the sweep (7.9 kN at 4500 rpm); orders 2, 3 "
            "and 4 peak where their harmonic meets it: 2500 rpm (2.2 kN), 1700 rpm (1.3 kN), 1300 rpm (0.70 kN).",
            "All 22 speeds by harmonic balance; the many dotted marks below 1500 rpm are the weakly meshed modes "
            "(703–1221 Hz, 7–19 % mesh energy) met by orders 2–4, which the journal bearings' damping leaves "
            "without a peak.")),
    Figure("baseline_dynamics_K_v", "speed", "Dynamic factor K_v against speed (baseline)", SPEED,
           "dynamics_K_v.png", (P + "rating.py::plot_dynamic_factor", CLI + "dynamics_nvh.py::_dynamic_factor"),
           ("femgear's K_v, the largest dynamic over the static mesh force per helix, beside ISO 6336-1 method B; "
            "the top axis is ISO's resonance ratio N = n₁/n_E1.",
            "Method B lies far above femgear's K_v (at most 1.07, near N = 1) and jumps at N_S, where its main "
            "resonance range (shaded) begins.")),
    Figure("marine_dynamics_K_v", "speed", "Dynamic factor K_v against speed (marine)", SPEED_M,
           "dynamics_K_v.png", (P + "rating.py::plot_dynamic_factor", CLI + "dynamics_nvh.py::_dynamic_factor"),
           ("femgear's K_v stays within 5 % of 1 through ISO's main resonance range (shaded), where method B "
            "steps up to 1.16.",
            "ISO's resonance speed n_E1 = 3736 rpm puts f_m at 1.8 kHz; femgear's torsional mode with 92 % mesh "
            "energy is at 2.41 kHz (`--modes`), met only at about 5000 rpm.")),
    Figure("baseline_dynamics_campbell", "speed", "Campbell diagram (baseline)", CAMPBELL,
           "campbell.png", CAMPBELL_FIG,
           ("The natural frequencies against the driver speed (gyroscopic, tracked mode to mode by MAC), the mesh "
            "orders 1–4 (dashed) and shaft orders (dotted); coloured: modes with ≥ 5 % mesh strain energy, "
            "labelled with their shares.",
            "Circles are the critical speeds of `campbell.json`: the 2851 Hz mode met by mesh orders 4, 3, 2, 1 "
            "at 1380, 1840, 2759 and 5519 rpm, the 8.1 and 8.3 kHz modes by order 4 at 3920 and 4027 rpm; the "
            "lines stay flat: the gyroscopic moments move these modes little.")),
    Figure("marine_dynamics_campbell", "speed", "Campbell diagram (marine)", CAMPBELL_M,
           "campbell.png", CAMPBELL_FIG,
           ("Five modes with mesh strain energy below 3 kHz: 703, 849 and 1221 Hz (bearing modes, 7–19 % in the "
            "mesh), the 2412 Hz torsional mode (92 %) and 2804 Hz (33 %): 18 critical speeds up to 4500 rpm.",
            "The one that matters is the 2412 Hz mode: mesh orders 4, 3 and 2 meet it at 1248, 1663 and 2495 rpm, "
            "the peaks of the order sweep above; order 1 would meet it only at about 5000 rpm.")),
    Figure("baseline_dynamics_runup", "speed", "Run-up with order tracking: the mesh force (baseline)", RUNUP,
           "runup.png", RUNUP_FIG,
           ("A run-up from 800 to 2000 rpm in 2 s, order-tracked: the colour map of the mesh force's pinion "
            "orders against speed (top; the lines at whole mesh orders) and the cuts along mesh orders 1–4 "
            "(bottom).",
            "The ramp passes the 2.85 kHz mode with order 4 at 1391 rpm (18.6 N) and order 3 at 1837 rpm; the "
            "circles, the steady state at each speed, lie on the cuts except at these peaks, where the ramp lags "
            "them by 4.3 % and 1.6 %.")),
    Figure("baseline_dynamics_runup_bearing", "speed", "Run-up with order tracking: a bearing load (baseline)", RUNUP,
           "runup_bearing.png", RUNUP_FIG,
           ("The same run-up read on the bearing-load component with the largest first mesh order (gear_L x): the "
            "map and the mesh-order cuts as for the mesh force.",
            "Order 1 stays at 3.3–3.5 N over the ramp; the order-4 resonance at 1391 rpm lifts its line to 12.7 N, "
            "nearly four times order 1, and order 3's resonance at 1837 rpm shows as well.")),
    # ---- housing
    Figure("baseline_housing_orders", "housing", "Sensor accelerations and sound power of an FE housing (baseline)",
           HOUSING, "housing_orders.png", (P + "housing.py::plot_housing_orders", IO + "housing.py::write_housing"),
           ("The linear response per mesh order at four sensors on the top wall of the parametric FE housing "
            "(Craig–Bampton coupled into the dynamics), 500–9000 rpm, and the sound power the housing radiates "
            "(ERP, σ = 1, bottom right).",
            "On the flexible housing the rotor's first mode falls from 2851 Hz (rigid) to 776 Hz; the sensors "
            "rise by five decades to peaks of 30–37 m/s² near 6900–7900 rpm, where L_W reaches 81 dB; the dotted "
            "line is the operating speed.")),
    # ---- LTCA
    Figure("baseline_ltca_te_curves", "ltca", "Loaded transmission error over a mesh period", LTCA,
           "te_curves.png", (P + "ltca.py::plot_te_curves", LTCA_FIG),
           ("The mean level grows nearly in proportion to the torque (the teeth's compliance); the swing over the "
            "mesh period, the peak-to-peak in the legend, is what excites the vibration.",
            "Each helix alone (dashed; dotted, on top of it for stagger 0) lies a little below both together; "
            "the unloaded TE (grey) is zero: some contact line always touches unrelieved involute.")),
    Figure("baseline_ltca_harmonics", "ltca", "Harmonics of the loaded transmission error", LTCA,
           "te_harmonics.png", (P + "ltca.py::plot_harmonics", LTCA_FIG),
           ("The peak amplitude of each mesh order of the loaded TE, per torque: the excitation of the dynamics, "
            "order by order; here it falls by about a factor of ten from order 1 to order 4.",
            "The black marks, the same cycle with twice the points per contact line, sit close to the bars: "
            "their difference is the harmonics' discretisation error.")),
    Figure("baseline_ltca_harris", "ltca", "Harris map: TE peak-to-peak against torque", LTCA,
           "harris.png", (P + "ltca.py::plot_harris", LTCA_FIG),
           ("Unmodified teeth (dashed) swing in proportion to the torque; the tip relief holds the swing at "
            "0.33–0.39 µm from about 150 N m up, 30 % below the unmodified pair's at the design torque (dotted).",
            "At light torque the relief itself is the swing: below the crossing (about 120 N m) the modified "
            "pair is the noisier one, the trade-off a Harris map is drawn for.")),
    Figure("baseline_ltca_load", "ltca", "Load over the pinion flank at the worst phase", LTCA, "load_T200Nm.png",
           (P + "ltca.py::plot_load_distribution", LTCA_FIG),
           ("The contact lines in mesh at the phase of the largest pressure, on each helix's flank unrolled "
            "(profile roll distance up, face width across): they cross the face diagonally.",
            "The short line entering at the pinion's root next to the apex carries the most; the red crosses are "
            "loaded nodes on the flank's edge, where a line contact's pressure does not hold.")),
    Figure("baseline_ltca_pressure", "ltca", "ParaView: the LTCA's largest pressure over the flank", LTCA,
           "ltca_maps_T200Nm.pvd", (LTCA_FIG,),
           ("The largest contact pressure each point of the pinion's flank sees over a mesh cycle at 200 N m "
            "(`ltca_maps_T200Nm.pvd`; the FE body's helices have the other hand than `flanks.pvd`'s).",
            "A broad band of nearly even pressure in each helix rises to ridges where the tip reliefs begin and "
            "falls to nothing on the relieved strips; the highest value sits at the apex, root side."),
           render=Render("p_max", MPA, "largest pressure over the cycle [MPa]", title="pinion flank, 200 N m")),
    # ---- EHL
    Figure("baseline_ehl_line", "ehl", "Line-contact EHL at the baseline's pitch point",
           "femgear ehl line --M 4.153 --L 14.20 --roelands --ph 5.249e8", "ehl_line_centreline.png",
           (P + "ehl.py::plot_centreline", IO + "ehl.py::write_all"),
           ("Pressure P = p/p_H (blue) and film H (red) across the contact, the oil entering from the left: a "
            "flat film in the Hertzian zone, closing to its minimum at the outlet.",
            "At this light load (M ≈ 4) the pressure never reaches a Hertzian dome and the outlet's spike stands "
            "at about 1.75 times the Hertz pressure; the inlet starts at 4 times the fully flooded distance the "
            "solver sizes it to.  The title's Hc and Hmin are in Moes' film unit, not the axis's h R/a².")),
    Figure("marine_ehl_line", "ehl", "Line-contact EHL at the marine pair's pitch point",
           "femgear ehl line --M 16.22 --L 11.63 --roelands --ph 9.343e8", "ehl_line_centreline.png",
           (P + "ehl.py::plot_centreline", IO + "ehl.py::write_all"),
           ("The heavier load (M ≈ 16) gives the textbook picture: a nearly Hertzian pressure with a spike of "
            "about 1.3 p_H just ahead of the outlet constriction.",
            "The film is flat over the Hertzian zone; the minimum film at the constriction is about ¾ of the "
            "central one (the title: Hmin/Hc = 0.75), the classic rule of thumb.")),
    # ---- sweeps
    Figure("baseline_sweep_summary", "sweep", "A speed–torque sweep of the baseline",
           "femgear sweep docs/gallery/baseline_sweep.toml --workers 1", "gallery_sweep/summary.png",
           (P + "sweep.py::plot_sweep_summary", "femgear/edge/sweep/figure.py::write_summary"),
           ("One panel per output, speed across, one line per torque: the Hertz pressure depends on the torque "
            "only (∝ √T), the minimum film grows with speed as u^0.7 and falls a little with torque.",
            "μ rises with torque (0.018 to 0.027) and moves by under 10 % with speed; the DTE RMS doubles with the "
            "torque and does not move with speed: far below every mode, the response is quasi-static.")),
)

#: code every figure passes through: the pyplot import, the PNG writer, the gallery's own PNG encoding
COMMON = ("femgear/edge/plot/__init__.py::pyplot", "femgear/edge/io/figures.py::save_figure",
          "docs/gen/gallery.py::encode_png")
#: the code of the rendered figures
RENDER_CODE = ("docs/gen/render.py::render_flank",)


# ---------------------------------------------------------------- the inputs' digest


def _strip_docstrings(tree: ast.AST) -> None:
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Module)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(getattr(body[0], "value", None), ast.Constant) \
                    and isinstance(body[0].value.value, str):
                node.body = body[1:] or [ast.Pass()]


def code_text(ref: str) -> str:
    """``path::name``: the parsed code (no docstrings, no comments, no layout) of the top-level function, class
    or constant ``name`` of the module at ``path`` and of the module-level names it uses, transitively."""
    path, _, name = ref.partition("::")
    tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
    _strip_docstrings(tree)
    top: dict[str, ast.AST] = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            top[node.name] = node
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            for target in node.targets if isinstance(node, ast.Assign) else [node.target]:
                for n in ast.walk(target):
                    if isinstance(n, ast.Name):
                        top[n.id] = node
    if name not in top:
        raise KeyError(f"{ref}: {path} has no top-level {name!r}")
    seen: list[str] = []
    todo = [name]
    while todo:
        n = todo.pop()
        if n in seen:
            continue
        seen.append(n)
        todo += [s.id for s in ast.walk(top[n]) if isinstance(s, ast.Name) and s.id in top and s.id not in seen]
    return "\n".join(ast.dump(top[n]) for n in sorted(seen))


def input_files(command: str) -> list[Path]:
    """The files a command reads: its ``.toml`` arguments, and the base scene a sweep file names."""
    out: list[Path] = []
    for token in shlex.split(command):
        path = ROOT / token
        if token.endswith(".toml") and path.is_file():
            out.append(path)
            base = tomllib.loads(path.read_text(encoding="utf-8")).get("base")
            if isinstance(base, str):
                out.append((path.parent / base).resolve())
    return out


def _data(path: Path) -> str:
    """A TOML file as canonical JSON: its comments and layout do not count."""
    return json.dumps(tomllib.loads(path.read_text(encoding="utf-8")), sort_keys=True)


def inputs_digest(fig: Figure) -> str:
    """The digest of everything that makes ``fig``'s picture (the module docstring says what is left out)."""
    h = hashlib.sha256()
    recipe = {"command": fig.command, "output": fig.output, "colours": None if fig.render else COLOURS,
              "render": asdict(fig.render) if fig.render else None}
    h.update(json.dumps(recipe, sort_keys=True).encode())
    for path in input_files(fig.command):
        h.update(path.relative_to(ROOT).as_posix().encode() + b"\0" + _data(path).encode())
    for ref in sorted(set(fig.code) | set(COMMON) | (set(RENDER_CODE) if fig.render else set())):
        h.update(ref.encode() + b"\0" + code_text(ref).encode())
    return h.hexdigest()[:16]


def read_manifest() -> dict:
    if not MANIFEST.exists():
        return {}
    return json.loads(MANIFEST.read_text(encoding="utf-8")).get("figures", {})


def stale(figures=FIGURES) -> list[Figure]:
    """The figures whose picture is missing or whose recorded digest is not the current one."""
    recorded = read_manifest()
    return [f for f in figures if not (GALLERY / f"{f.name}.png").exists()
            or recorded.get(f.name, {}).get("inputs") != inputs_digest(f)]


# ---------------------------------------------------------------- the page


def figure_block(fig: Figure, prefix: str = "") -> str:
    """Markdown of one figure: the picture (``prefix`` leads from the page to the docs root), the command, the
    two lines; a note instead of the picture while it is not generated."""
    png = GALLERY / f"{fig.name}.png"
    picture = (f"![{fig.title}]({prefix}gallery/{fig.name}.png)" if png.exists()
               else f"*Not generated yet: `python docs/gen/gallery.py --only {fig.name}`.*")
    what = "renders `" + fig.output + "` off-screen (pyvista)" if fig.render else "writes `" + fig.output + "`"
    return "\n".join([picture, "", "```sh", fig.command, "```", "",
                      f"The command {what}. What to read in it:", "", f"- {fig.read[0]}", f"- {fig.read[1]}", ""])


def page() -> str:
    """``gallery.md``: every figure of :data:`FIGURES` by group, in the order of :data:`GROUPS`."""
    recorded = read_manifest()
    seconds = sum({v.get("command"): v.get("seconds", 0.0) for v in recorded.values()}.values())
    out = ["# Gallery of figures", "",
           "Every figure femgear draws, made by femgear's own commands from the zoo's scenes "
           "(`studies/zoo/`): the paper's baseline pair and, where it shows something else, the marine "
           "reduction (3 MW, 2 × 120 mm helices, journal bearings). Each picture is the PNG the command writes "
           "(the plots stored with a 128-colour palette), with the command that makes it and two lines on what to "
           "read in it. Two commands run at the coarse numerics of `physics.preset = \"fast\"` (21 points along "
           "the path, 100 steps per mesh period), where the figure reads the same: the worn run, whose curves show "
           "the 21 points as kinks near the pitch point, and the sweep of many load cases.", "",
           f"The pictures are made by `python docs/gen/gallery.py` (`make gallery`, about {seconds / 60:.0f} "
           "minutes of femgear on two cores) and checked for staleness by `tests/docs/test_gallery.py`: it "
           "fails when a scene, a command or the code that draws a figure changed since its picture was made "
           "([How the docs are built](documentation.md)).", ""]
    for key, (heading, intro) in GROUPS.items():
        figs = [f for f in FIGURES if f.group == key]
        if figs:
            out += [f"## {heading}", "", intro, ""]
            for f in figs:
                out += [f"### {f.title}", "", figure_block(f)]
    return "\n".join(out)


#: a line of a Markdown page that shows a figure of the table (``docs/gen/hooks.py``)
MARKER = re.compile(r"^<!-- figure: ([A-Za-z0-9_]+) -->$", re.MULTILINE)


def expand(markdown: str, prefix: str = "") -> str:
    """``markdown`` with each :data:`MARKER` line replaced by :func:`figure_block` of its figure; KeyError names a
    marker whose figure is not in the table."""
    by_name = {f.name: f for f in FIGURES}

    def block(match: re.Match) -> str:
        if match.group(1) not in by_name:
            raise KeyError(f"{match.group(0)}: no figure {match.group(1)!r} in docs/gen/gallery.py")
        return figure_block(by_name[match.group(1)], prefix)

    return MARKER.sub(block, markdown)


# ---------------------------------------------------------------- making the pictures


def encode_png(source: Path, target: Path, colours: int | None = COLOURS) -> int:
    """``source`` re-encoded at ``target`` (through a temporary file) as a palette PNG of ``colours`` colours (no
    dither: the figures' flat colours stay flat), or with ``colours=None`` as RGB; no metadata, so the same picture
    gives the same bytes.  Returns the file's size [bytes]."""
    from PIL import Image

    image = Image.open(source).convert("RGB")
    if colours is not None:
        image = image.quantize(colors=colours, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    tmp = target.with_suffix(".tmp")
    image.save(tmp, format="PNG", optimize=True)
    os.replace(tmp, target)
    return target.stat().st_size


def _folder(command: str) -> Path:
    return WORK / hashlib.sha1(command.encode()).hexdigest()[:10]


def run_command(command: str) -> tuple[Path, float]:
    """Run ``command`` (``femgear ...``) with ``-q`` into a fresh folder under ``out/gallery``; (folder, wall s)."""
    args = shlex.split(command)
    if args[0] != "femgear":
        raise ValueError(f"not a femgear command: {command!r}")
    folder = _folder(command)
    shutil.rmtree(folder, ignore_errors=True)
    folder.parent.mkdir(parents=True, exist_ok=True)
    env = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", **os.environ}
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "femgear", "-q", *args[1:], "--out", str(folder)], cwd=ROOT,
                          env=env, capture_output=True, text=True)
    if proc.returncode != 0:
        last = (proc.stderr.strip().splitlines() or ["(no message)"])[-1]
        raise RuntimeError(f"exit {proc.returncode}: {last}")
    return folder, time.perf_counter() - start


def make(fig: Figure, folder: Path) -> int:
    """The picture of ``fig`` from its command's output ``folder`` into ``docs/gallery``; its size [bytes]."""
    produced = folder / fig.output
    if not produced.exists():
        raise FileNotFoundError(f"the command wrote no {fig.output}")
    if fig.render is not None:
        raw, r = folder / f"{fig.name}.render.png", fig.render
        proc = subprocess.run([sys.executable, str(Path(__file__).with_name("render.py")), str(produced), r.field,
                               str(raw), "--scale", repr(r.scale), "--label", r.label, "--part", str(r.part),
                               "--title", r.title], capture_output=True, text=True)
        if proc.returncode != 0:
            last = re.sub(r"\x1b\[[0-9;]*m", "", (proc.stderr.strip().splitlines() or [f"exit {proc.returncode}"])[-1])
            raise RuntimeError(f"the off-screen view failed (it needs pyvista and EGL with Mesa: `make sysdeps`, "
                               f"docs/gen/render.py): {last.strip()}")
        return encode_png(raw, GALLERY / f"{fig.name}.png", colours=None)
    return encode_png(produced, GALLERY / f"{fig.name}.png")


def generate(figures) -> int:
    """Make ``figures`` (each command once), record their digests; the number that failed."""
    manifest = read_manifest()
    failed = 0
    by_command: dict[str, list[Figure]] = {}
    for f in figures:
        by_command.setdefault(f.command, []).append(f)
    for command, figs in by_command.items():
        print(f"gallery: {command}", flush=True)
        try:
            folder, seconds = run_command(command)
        except (RuntimeError, ValueError, OSError) as exc:
            failed += len(figs)
            print(f"gallery: FAILED {', '.join(f.name for f in figs)}: {exc}", file=sys.stderr)
            continue
        for f in figs:
            try:
                size = make(f, folder)
            except Exception as exc:  # one line per failed figure; the others go on
                failed += 1
                print(f"gallery: FAILED {f.name}: {type(exc).__name__}: {exc}", file=sys.stderr)
                continue
            manifest[f.name] = {"inputs": inputs_digest(f), "command": command, "seconds": round(seconds, 1)}
            print(f"gallery:   {f.name}.png  {size / 1e3:.0f} kB  ({seconds:.0f} s)", flush=True)
    known = {f.name for f in FIGURES}
    manifest = {k: v for k, v in sorted(manifest.items()) if k in known}
    MANIFEST.write_text(json.dumps({"about": "docs/gen/gallery.py: the digest of each figure's inputs",
                                    "figures": manifest}, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    for png in GALLERY.glob("*.png"):            # a figure removed from the table
        if png.stem not in known:
            png.unlink()
    return failed


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python docs/gen/gallery.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("--all", action="store_true", help="regenerate every figure")
    ap.add_argument("--only", default=None, metavar="NAME[,NAME]", help="regenerate these figures")
    ap.add_argument("--check", action="store_true", help="list the stale figures; exit 1 if any")
    ap.add_argument("--list", action="store_true", help="print the commands")
    args = ap.parse_args(argv)
    if args.list:
        for command in dict.fromkeys(f.command for f in FIGURES):
            print(command)
        return 0
    if args.only:
        names = [n.strip() for n in args.only.split(",") if n.strip()]
        unknown = sorted(set(names) - {f.name for f in FIGURES})
        if unknown:
            print(f"gallery: error: --only: no figure {unknown[0]!r} (see --list)", file=sys.stderr)
            return 2
        todo = [f for f in FIGURES if f.name in names]
    else:
        todo = list(FIGURES) if args.all else stale()
    if args.check:
        for f in stale():
            print(f"stale: {f.name}  (python docs/gen/gallery.py --only {f.name})")
        return 1 if stale() else 0
    if not todo:
        print("gallery: every figure is up to date")
        return 0
    start = time.perf_counter()
    failed = generate(todo)
    print(f"gallery: {len(todo) - failed} of {len(todo)} figures made in {time.perf_counter() - start:.0f} s"
          + (f"; {failed} FAILED" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
