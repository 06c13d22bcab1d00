"""``python -m structure`` has moved: the command line lives at the top of kinematics."""

import sys

sys.stderr.write("the assur command line moved: run 'assur' or 'python -m kinematics'\n")
sys.exit(2)
