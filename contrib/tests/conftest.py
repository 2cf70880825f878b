import os
import sys

# The package lives beside the scripts in contrib/.
sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..")))
