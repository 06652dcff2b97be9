# GRFLOW analysis: read a run directory written by the GRFLOW decks and
# extract the quantities of the isochoric cyclic shearing paper.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The analysis of a GRFLOW run directory; ``grflow-figures``
(:mod:`grflow_analysis.figures`) draws the paper's figures with it.

Everything here is a pure function of its arguments (no plotting, no
printing); rows of the series are referred to by their index in the
arrays returned by :func:`read_series`.  The analysis is four modules,
each importing only those above it; all their names, private helpers
included, are imported here, and the package's users call them
``grflow_analysis.NAME``:

* :mod:`grflow_analysis.readers`: the readers of the run directory
  (inputs/README.md), :class:`FormatError`, the column names of the
  series and the settings the shear stage ran with;
* :mod:`grflow_analysis.cycles`: fix grflow/shear's events on the series,
  the fractional cycle count N, initial liquefaction and its exits, the
  states of a cycle (its docstring holds these definitions);
* :mod:`grflow_analysis.metrics`: quantities measured on the series: P_c,
  peak a_c per cycle, static redundancy, the logistic fit of the z_g rise
  at each exit (inflection, knee), statistics of the inertial number;
* :mod:`grflow_analysis.report`: the paper's values (PAPER) and the
  summary of a run beside them, as a dict and as a markdown table.

The commands' modules (:mod:`~grflow_analysis.figures`,
:mod:`~grflow_analysis.curve`, :mod:`~grflow_analysis.study`) and
:mod:`~grflow_analysis.definitions` (the summary's optional definitions)
use the package through these names; it does not import them.
"""

# the package's names, one source each
from .readers import (DEFAULT_RU_LIQ, DEFAULT_TAU_AMP, EVENT_COLUMNS, PC_COLUMNS,
                      REQUIRED_COLUMNS, SERIES_COLUMNS, FormatError, _canonical,
                      _drop_repeated_steps, _is_number, _load_rows, _locate_bad_row,
                      list_snapshots, protocol, read_dump, read_dump_atoms,
                      read_dump_local, read_events, read_prep, read_series,
                      read_shear_record, stage_values)
from .cycles import (STATES, choose_cycle, cycle_count, cycle_rows, find_cycle_states,
                     fix_events, liquefaction, liquefaction_n, post_liquefaction_cycles,
                     run_events)
from .metrics import (INFLECTION_HALF_WINDOW_N, KNEE_FRACTION, NOT_AVAILABLE, NOT_REACHED,
                      Z_ISOSTATIC, _logistic_fit, connectivity, connectivity_non_floaters,
                      inertial_stats, logistic_knee, peak_ac_per_cycle, static_redundancy,
                      zg_inflections)
from .report import (PAPER, _difference, _entry, _fmt, _match, _num, match_cell, summary,
                     summary_markdown, tolerance_cell)
