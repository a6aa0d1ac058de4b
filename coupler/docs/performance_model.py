#!/usr/bin/python3
"""Performance model of a decomposed run (issue 27): the time of one step on
P ranks from the measured compute cost per cell or point on one core and the
halo exchanges and reductions each solver's step makes, on a cluster whose
network is given by its latency and bandwidth. Prints the parallel
efficiency E(P) = T(1) / (P T(P)). See performance_model.md."""
import math
import sys

# The network of a typical cluster (parameters, not measurements).
ALPHA = 2.0e-6    # latency of one MPI message between nodes [s] (InfiniBand HDR, MPI software included)
BETA = 2.0e9      # bandwidth per rank when every rank of a node sends at once [B/s] (~12.5 GB/s per node / 6 busy links)


def allreduce(ranks):
    """Small allreduce by recursive doubling: 2 log2(P) latencies."""
    return 0.0 if ranks == 1 else 2.0 * math.ceil(math.log2(ranks)) * ALPHA


def process_grid(ranks, nx, ny):
    """The factorisation px x py of P with the least cut faces (cosim's process_grid)."""
    best = None
    for px in range(1, ranks + 1):
        if ranks % px:
            continue
        py = ranks // px
        if px > nx or py > ny:
            continue
        faces = (px - 1) * ny + (py - 1) * nx
        if best is None or faces < best[0]:
            best = (faces, px, py)
    return best[1], best[2]


def halo(ranks, nx, ny, layers, values_per_cell):
    """One exchange of `layers` ghost layers of `values_per_cell` doubles with
    every neighbour of an interior block: its latencies and bytes."""
    if ranks == 1:
        return 0.0
    px, py = process_grid(ranks, nx, ny)
    bx, by = nx / px, ny / py
    messages = (2 if px > 1 else 0) + (2 if py > 1 else 0)
    face_cells = (2 * by if px > 1 else 0) + (2 * bx if py > 1 else 0)
    return messages * ALPHA + layers * face_cells * values_per_cell * 8.0 / BETA


def multigrid_levels(ranks, nx, ny):
    """Levels of a V-cycle distributed over the ranks: down to 2 x 2 cells a
    block; below that, the coarse grid is gathered on one rank (an allgather)."""
    px, py = process_grid(ranks, nx, ny)
    return max(1, int(math.log2(max(2.0, min(nx / px, ny / py)))))


ICE_GHOSTS = 5  # ice_fluid's ghost layers toward each neighbouring block


def ice_step(ranks, nx, ny, seconds_per_cell, cg_iterations):
    """ICE as ice_fluid is built (Tran et al., MPMICE, Sec. 3): each rank
    steps its block widened by 5 ghost layers toward each neighbour (that
    redundant work counts as compute); per step two halo exchanges of 5
    layers, dP (1 value) after the pressure solve and the state the next step
    reads at its end (19 values in 2D with two fluids: pressure, porosity,
    mixture kappa, 2 solid velocity components, and per fluid bulk density,
    temperature, density, volume fraction, specific volume, kappa and 2
    velocity components); 6 reductions (time step, Courant number, upwind
    check, refused step, volume closure, equilibration report). The pressure
    solve (PETSc's CG with an algebraic multigrid): per CG iteration one
    halo of the pressure (1 layer) for the matrix product, a V-cycle with 5
    halos per level (smoothing down and up, residual, restriction,
    prolongation) and its coarse solve, 2 dot products."""
    px, py = process_grid(ranks, nx, ny)
    widened_x = nx / px + ICE_GHOSTS * min(px - 1, 2)
    widened_y = ny / py + ICE_GHOSTS * min(py - 1, 2)
    compute = seconds_per_cell * widened_x * widened_y
    levels = multigrid_levels(ranks, nx, ny)
    coarse = allreduce(ranks)  # the gathered coarse grid
    per_iteration = ((1 + 5 * levels) * halo(ranks, nx, ny, 1, 1) + coarse
                     + 2 * allreduce(ranks))
    explicit = (halo(ranks, nx, ny, ICE_GHOSTS, 1) + halo(ranks, nx, ny, ICE_GHOSTS, 19)
                + 6 * allreduce(ranks))
    return compute, explicit + cg_iterations * per_iteration


SLAB_ROWS = 4  # cell rows of the MPM scatter's slabs: the finest cut


def mpm_ranks(ranks, ny):
    """The ranks the MPM can use: its grid is cut into slabs of whole cell
    rows along the last direction, at least one 4-row slab a rank."""
    return min(ranks, ny // SLAB_ROWS)


def mpm_step(ranks, nx, ny, seconds_per_point, points):
    """MPM as decomposed (architecture.md §15): slabs of cell rows along y,
    each rank with its two neighbours. Per step: the ghost planes' partial
    sums after P2G (mass, momentum, force, even and odd slabs: 10 values),
    the updated velocities back to the ghosts (4), the MUSL re-map's sums
    (4) and re-mapped velocities (2), over 3 planes of nx + 1 nodes (GIMP: 1
    below, 2 above): 60 (nx + 1) doubles a rank, in 8 messages (measured:
    18,088 values a step on 2 ranks of the 531-cell-wide column, which this
    gives); the time step's 2 reductions; the migration: a reduction that
    agrees no point goes past a neighbour, then a count and the points (one
    layer in twenty of a face's points a step, 330 B a point) to each
    neighbour. Runs on at most ny / 4 ranks (mpm_ranks)."""
    ranks = mpm_ranks(ranks, ny)
    compute = seconds_per_point * points / ranks
    if ranks == 1:
        return compute, 0.0
    grid = 8 * ALPHA + 60 * (nx + 1) * 8.0 / BETA
    points_per_cell = points / (nx * ny)
    migration = (allreduce(ranks) + 4 * ALPHA
                 + 0.05 * points_per_cell * 2 * nx * 330.0 / BETA)
    return compute, grid + migration + 2 * allreduce(ranks)


def swe_step(ranks, nx, ny, seconds_per_cell):
    """SWE 2D: two halo exchanges of h, hu, hv (2 layers), the dt reduction."""
    compute = seconds_per_cell * nx * ny / ranks
    return compute, 2 * halo(ranks, nx, ny, 2, 3) + allreduce(ranks)


def efficiency(step, ranks):
    compute_1, comm_1 = step(1)
    compute_p, comm_p = step(ranks)
    return (compute_1 + comm_1) / (ranks * (compute_p + comm_p)), comm_p / (compute_p + comm_p)


def main():
    rank_counts = [2, 64, 1024, 4096]
    # Measured on one core of the 2-core VM (the closing note of the session):
    # the debris flow at the paper's resolution, 700 x 400 cells, 353,545 points,
    # 30 windows of 10 us: ICE 0.323 s a step (1.15 us a cell, 10.7 CG iterations
    # a step), MPM 0.470 s a step (1.33 us a point); 1.3 ICE steps and 1 MPM step
    # a window.
    nx, ny = 700, 400
    ice = lambda p: ice_step(p, nx, ny, 0.323 / (nx * ny), 10.7)
    mpm = lambda p: mpm_step(p, nx, ny, 0.470 / 353545, 353545)

    def debris_window(p):
        ci, mi = ice(p)
        cm, mm = mpm(p)
        # The two solvers on the same ranks' cores one after the other (each
        # participant on P ranks, the windows staggered), 1.3 ICE steps a window.
        return 1.3 * ci + cm, 1.3 * mi + mm

    print(f"network: latency {ALPHA * 1e6:g} us, bandwidth {BETA / 1e9:g} GB/s per rank")
    print("debris flow, 700 x 400 cells, 353,545 points (Tran et al., MPMICE), per window")
    print(f"(the MPM on at most {ny // SLAB_ROWS} ranks, its slabs of {SLAB_ROWS} rows; the ICE on all):")
    print(f"{'ranks':>6} {'cells/rank':>10} {'compute ms':>11} {'comm ms':>9} {'comm share':>10} {'E':>6}")
    for p in rank_counts:
        compute, comm = debris_window(p)
        e, share = efficiency(debris_window, p)
        print(f"{p:6d} {nx * ny / p:10.0f} {1e3 * compute:11.3f} {1e3 * comm:9.3f} {share:10.1%} {e:6.1%}")
    print("SWE 2D (59.2 ns a cell-update, measured), 1e8 cells (10,000 x 10,000):")
    swe = lambda p: swe_step(p, 10000, 10000, 59.2e-9)
    for p in rank_counts:
        compute, comm = swe(p)
        e, share = efficiency(swe, p)
        print(f"{p:6d} {1e8 / p:10.0f} {1e3 * compute:11.3f} {1e3 * comm:9.3f} {share:10.1%} {e:6.1%}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
