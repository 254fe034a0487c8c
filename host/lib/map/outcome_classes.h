/* outcome_classes.h - the one table of the outcome classes of a free run
 * (docs/maps.md section 2): what the classifier applies (outcome.c), what
 * the tables name (map.csv's frac_NAME columns), what map-plot draws (its
 * palette and legend) and what the reports read (host/reports/
 * maps_report.sh takes the names from here).
 *
 * X(ID, name, label, colour, precedence, rule):
 *   ID          the enum's OUTCOME_ID; the row's place is the class's index
 *               (map.csv's column order, the tie-break of a point's
 *               majority: keep it when adding a class, add at the end)
 *   name        the class in tables, an identifier (also the rule's
 *               function in outcome.c: holds_NAME)
 *   label       the class in prose and legends
 *   colour      map-plot's colour ("#rrggbb")
 *   precedence  the order in which the rules are tried, 1 first: the first
 *               whose rule holds is the class
 *   rule        the rule in words (A, S: the 1 s centred moving averages of
 *               the amplitude w(4L/7) / h and of s; the settled window: the
 *               run's last 10 s, or the whole run if shorter; a rise: A
 *               above 0.5 h from the start or from below 0.25 h; a fall: A
 *               back below 0.25 h)
 */
#ifndef OUTCOME_CLASSES_H
#define OUTCOME_CLASSES_H

#define OUTCOME_CLASS_TABLE(X)                                                                              \
    X(TRIVIAL, trivial, "trivial adaptation", "#2ca02c", 5,                                                 \
      "no fall; S walks one way only (its largest retreat against its way below 0.005) and the mean "      \
      "amplitude over the settled window is above 0.5 h")                                                  \
    X(SIGNATURE, signature, "signature move", "#1f77b4", 4,                                                 \
      "no fall; before the first rise S fell more than 0.005 below s0, after it S walks back more than "   \
      "0.005 above its minimum")                                                                           \
    X(RELAXATION, relaxation, "relaxation oscillation", "#ff7f0e", 3,                                       \
      "at least two complete cycles (a rise and a fall of A)")                                              \
    X(SELF_DAMPING, self_damping, "self-damping", "#b0b0b0", 6,                                             \
      "A never exceeds 0.25 h and the mean amplitude over the settled window is below 0.05 h")              \
    X(STOP, stop, "slider at a stop", "#8c564b", 2,                                                         \
      "the mean s over the settled window lies within 0.005 of a clamp stop")                               \
    X(FAULT, fault, "fault", "#d62728", 1, "the run stopped before t_end (a core status)")                  \
    X(OTHER, other, "other", "#e377c2", 7,                                                                  \
      "none of the others (a run too short for a 1 s average, a single cycle, an amplitude between the "   \
      "branches, ...)")

#endif
