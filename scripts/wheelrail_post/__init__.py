"""wheelrail's post-processing: the run's files, the half-space reference, the
figures and report pages, the sweeps and studies. One module per job:

    atomic_file        writing a file under a temporary name, then renaming it
    bem                half-space numerics: Hertz, influence coefficients, the
                       normal solver, Kalker's TANG, friction laws
    halfspace          the half-space reference: the cases (elliptic, line),
                       the rolling solve at a creepage or force, the fields
    halfspace_checks   its verification checks (halfspace.py --check NAME)
    halfspace_cli      its command line (scripts/halfspace.py)
    compare            a run's files by column name; its patch against the
                       half-space solution at the patch's own load and traction
    report_page        the self-contained report.html
    plots              the paper's figures and a run's report (scripts/plot.py)
    sweep              traction sweeps over mu_n and laws (scripts/sweep.py)
    creep_curve        creep-force tables (scripts/creep_curve.py)
    convergence_study  mesh and time-step study, Coulomb (scripts/convergence_study.py)
    friction_study     the velocity-dependent law's study (scripts/friction_study.py)
    layout_report      C++ files and their largest functions (scripts/layout_report.py)
    standard_profiles  S1002, 60E1 and the paper's pair as files in mesh/profiles/
                       from their definitions, and their checks (scripts/make_profiles.py)
    profiles           profile files, rail inclination, wheelset shift, the rigid
                       contact points and the gap (scripts/profile_contact.py)

The command-line entry points are the few-line files beside this folder in
scripts/; Python puts a script's own directory first on sys.path, so they find
the package without any path set-up, and the modules import each other
relatively. Debian's /usr/bin/python3 with numpy, matplotlib and h5py.
"""
import os

# scripts/, the folder of the entry points (build/wheelrail is ../build from it)
SCRIPTS_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
