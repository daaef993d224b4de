# The reference 4 without its self-motion potential: q_d = q for both targets, so that the null
# space only damps. Away from the locks' own configurations N^T removes a potential given to the
# other target (joint 1 is no self-motion where the tip is off its axis, the elbow none where it is
# bent), so the catalogue's "Z0 and Y0 potentials swapped" answers as this law at almost every
# state: the grader named it, from the law test's one recorded call, though the Z0 run's first
# call (the tip on joint 1's axis, where the swap turns joint 1) tells the two apart. Seen to fail
# on the grader before issue 58 (every failed test named the swap; the runs that never reached
# their target showed no judged value).
set(TARGET p4.cpp)
set(FROM "  if (target == Target::kAlongZ0) q_d(2) = kRetractedElbow;  // retract the arm: bend the elbow
  if (target == Target::kAlongY0) q_d(0) = kTurnedJoint1;    // turn the arm's plane to face Y0
")
set(TO "  (void)target;  // no self-motion potential
")
