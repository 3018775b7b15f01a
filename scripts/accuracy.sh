#!/usr/bin/env bash
# docs/ACCURACY.md in one command: what accuracy costs in time, for each
# anchor scene and hard case, with the other engines' points.
#
#   scripts/accuracy.sh    (about 5 minutes on 2 cores; the first run also builds the bench preset)
#
# 1. scripts/peers.sh: builds the `bench` preset with ODE and Bullet and runs
#    bench/peers/peer_bench on the anchor scenes (3 repetitions, pile1000's
#    first 60 steps), the peers' table going to build/bench/accuracy/peers.md;
# 2. builds karma-tradeoff in the same `bench` build and sweeps the knobs on
#    the anchor scenes and the hard cases (pile1000 alone: 1 s, three
#    solver settings, one repetition: its exact solve costs tens of ms a
#    step), the joint projection on the jointed scenes and the contact
#    reuse distance on the stacking scenes, reading the peers' table for
#    their points;
# 3. writes docs/ACCURACY.md (the text below, then the tool's tables) and
#    the plots under docs/images/accuracy/.
# Everything the tool writes stays in build/bench/accuracy/ (CSV included).
set -euo pipefail
cd "$(dirname "$0")/.."

out=build/bench/accuracy
images=docs/images/accuracy
rm -rf "$out"
mkdir -p "$out" "$images"

echo "accuracy: the peers (scripts/peers.sh)" >&2
scripts/peers.sh --reps 3 --pile-steps 60 >"$out/peers.md"
cmake --build --preset bench -j2 --target karma-tradeoff >/dev/null
tool=build/bench/tools/tradeoff/karma-tradeoff

sweep="solver=exact,exact:8,iterative:10,iterative:50 epsilon=1e-4,1e-2 h=1/60,1/120"
scenes=car,topple,stack21,ragdoll,pile27,chain,heavy_on_light
pile_sweep="solver=exact,iterative:10,iterative:50"
"$tool" --scene "$scenes" --sweep "$sweep" --repeat 3 --peers "$out/peers.md" --out "$out/main"
"$tool" --scene pile1000 --seconds 1 --sweep "$pile_sweep" --repeat 1 --peers "$out/peers.md" --out "$out/pile"
projection_sweep="solver=exact,iterative:10 projection=0,2 h=1/60,1/120"
"$tool" --scene chain,ragdoll --sweep "$projection_sweep" --repeat 3 --peers "$out/peers.md" --out "$out/projection"
reuse_sweep="reuse=0,1e-4,1e-3"
"$tool" --scene topple,stack21,pile27 --sweep "$reuse_sweep" --repeat 3 --peers "$out/peers.md" --out "$out/reuse"

echo "accuracy: the step budget on topple and pile1000 (bench/step_budget)" >&2
cmake --build --preset bench -j2 --target step_budget >/dev/null
build/bench/bench/step_budget topple 2>/dev/null >"$out/budget-topple.md"
build/bench/bench/step_budget pile1000 120 2>/dev/null >"$out/budget-pile1000.md"

rm -f "$images"/*.png
cp "$out"/main/*.png "$out"/pile/*.png "$images"/
for f in "$out"/projection/*.png; do cp "$f" "$images/projection-$(basename "$f")"; done
for f in "$out"/reuse/*.png; do cp "$f" "$images/reuse-$(basename "$f")"; done

{
  cat <<TEXT
# What accuracy costs in time

Written by \`scripts/accuracy.sh\` (do not edit by hand: change the script or the tool and run it
again) on $(date -u +%Y-%m-%d), $(git rev-parse --short HEAD), on a machine of $(nproc) cores, in
the \`bench\` build (single precision, release, link-time optimised). The tables and plots come from
\`karma-tradeoff\` (\`tools/tradeoff/\`; \`karma-tradeoff --help\`), which anyone can run on these
scenes, the tutorials' scenes or their own scene.

## How to read this

Each scene runs once per setting of the sweep and once as the **reference**: the exact solver
(Kea's active set, no iteration cap, every collision pair tested every step) at a step 8 times smaller than the smallest swept step, in
the same build (single precision: the reference is as exact as this build can be, not a double
precision run). Every setting is repeated and timed three times, the repetitions interleaved so
that the machine's drift in speed touches all settings alike; **µs per step** is the median (of
collision, solve and integration; building the scene is not timed). The plots, the fronts and the
sentences use **µs per 1/60 s** of simulated time (µs per step × (1/60) / h), so that halving the
step pays for the twice as many steps it takes. The machine was shared with other builds while
this ran: compare points inside one plot, not with figures taken at another time.

The errors, at the instants k/60 s common to every step size:

- **drift**: the largest, over the run, root-mean-square distance of the bodies from where the
  reference run has them (m). Chaotic scenes (a pile, a rag doll after it lands) drift from any
  reference in time; drift says how soon.
- **joint error**: the largest gap of a joint (its point as carried by each of its bodies), m.
- **penetration**: the deepest contact penetration over the run, m.
- **energy error**, **momentum error**: the largest difference of kinetic plus potential energy
  (J) and of linear momentum (N s) from the reference run.
- **residual**: Kea's largest residual of a step (impulse units).
- **scene error**: the scene's own figure, the one the other engines report too (bench/peers):
  car, the distance from the analytic \`a t²/2\` (m); stacks, the top box's larger of its sideways
  drift and its drop beyond the closing of the starting gaps (m); rag doll and chain, the largest
  joint error; piles, the deepest penetration at the end (m).
- **held**: stable (finite, every body under 50 m/s) and the scene's own check met (SCENES.md:
  stacks standing, the car within 5% of the analytic motion, joints whole, nothing lost).

Each plot has one point per setting, log-log, the **Pareto front** (the settings no other
setting beats in both time and error) drawn as a line, failed runs as red crosses, and on the
scene-error plots the other engines at h = 1/60 with their defaults (ODE 0.16 \`dWorldStep\` and
\`dWorldQuickStep\` with 20 iterations, Bullet 3.24 with 10), measured in the same command just
before. Errors of 1e-7 or less are drawn at 1e-7. Under each plot a sentence says what its front
says: which change of knob buys the most accuracy per microsecond along it.

Swept: \`$sweep\` (pile1000: \`$pile_sweep\`, 1 s). Settings name only the knobs they change;
\`epsilon\` is the constraint softness, \`h\` the step, \`exact:8\` the exact solver capped at 8
iterations, \`iterative:N\` projected Gauss-Seidel with N sweeps.

TEXT
  sed -e 's#(\([a-z0-9_]*-\(scene\|drift\)\.png\))#(images/accuracy/\1)#' -e 's|^### |## |' "$out/main/tradeoff.md"
  sed -e 's#(\([a-z0-9_]*-\(scene\|drift\)\.png\))#(images/accuracy/\1)#' -e 's|^### |## |' "$out/pile/tradeoff.md"
  cat <<TEXT

## The joint projection

\`MdtWorldSetJointProjection(world, n)\` (off by default; docs/STABILITY.md) closes the point
joints' gaps after every step with up to n Newton iterations of position impulses; the velocity
step is unchanged. What it costs and buys on the two jointed scenes, with both solvers and two
steps: \`$projection_sweep\`. Errors are against the same reference as above (the exact solver
at a step 8 times smaller, without projection).

TEXT
  sed -e 's#(\([a-z0-9_]*-\(scene\|drift\)\.png\))#(images/accuracy/projection-\1)#' "$out/projection/tradeoff.md"
  cat <<TEXT


## Contact reuse

\`McdFrameworkSetContactReuseDistance(framework, d)\` (default 1e-4 m at length scale 1, at most a
thousandth of the smaller shape's reach; engine/mcd/framework/contact_reuse.h) lets a resting pair
of boxes, cylinders, sphyls or convex meshes skip its nearfield test: its last contacts, carried by
both models, are reported while the pair's relative pose has moved no surface point by more than d. A served contact's position may
be up to the drift off a full test's; its separation follows the motion. What the distance costs
and buys on the stacking scenes: \`$reuse_sweep\` (0: every pair tested every step). Errors are
against the same reference as above, which tests every pair every step.

TEXT
  sed -e 's#(\([a-z0-9_]*-\(scene\|drift\)\.png\))#(images/accuracy/reuse-\1)#' "$out/reuse/tradeoff.md"
  cat <<TEXT

## The step budget

\`MdtWorldSetStepBudget(world, microseconds)\` lets the engine choose, per partition and per step,
the most accurate of exact, exact:8 and the iterative solver with 10 to 50 sweeps whose predicted
cost fits the partition's share of the budget (\`engine/mdt/step/step_budget.h\`). A partition is
priced by the solves or sweeps it made last step (a warm-started partition at rest stops after one
or two). It moves to a less accurate level at once when its level no longer fits, and back to a
more accurate one only after 15 steps at its present level, so that noise in the clock does not
toggle it. A level that has not run for a while is priced lower (down to a third of its learned
price over 60 steps), so a level priced out by one expensive step, such as a landing, is tried
again and learns its cost anew. The tables come from
\`build/bench/bench/step_budget topple\` and \`step_budget pile1000 120\`: every figure is the median
of three runs made setting by setting in turn. Two dynamics times are measured first: the exact
solver's (an unbounded budget) and the floor (a starved budget: the step outside the solves plus
the cheapest solves, which no budget can go below); the budgets are fractions of the first, and
one below the floor is marked so. "dynamics us / budget" is the median of the measured
\`MdtWorldStep\` time over the budget (the budget covers the dynamics, not collision); "steps within
20%" the share of steps whose dynamics time was within 20% of the budget; the last column the range of
the errors of the fixed settings whose whole step costs no more than the budgeted run's: what that
time buys without a budget. A budget's error is set mostly in the first steps, when the stacks
land: a landing step costs the exact solver more than its average step, so even a budget of 100%
of the exact solver's average time solves the landing iteratively. On these scenes the solves are a minority of the step
(each table's first line gives its floor as a share of the exact step), so the range a budget can buy is
narrow.

### topple

TEXT
  cat "$out/budget-topple.md"
  printf '\n### pile1000 (its first 120 steps)\n\n'
  cat "$out/budget-pile1000.md"
} >docs/ACCURACY.md
echo "accuracy: wrote docs/ACCURACY.md and $images/ (the CSV: $out/main/tradeoff.csv, $out/pile/tradeoff.csv)" >&2
