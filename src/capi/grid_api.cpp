// SPDX-License-Identifier: GPL-2.0-or-later
// asp_grid_*: creation, queries and FFT planning of grids.
#include "capi/constants.hpp"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "core/checks.hpp"

using asp::capi::guarded;

namespace {
int create_grid(const char *function, int dimension, int64_t nx, int64_t ny, double lx,
                double ly, asp_grid **out) {
  if (out != nullptr) *out = nullptr;
  return guarded(function, [&] {
    asp::require_not_null(out, "out");
    std::unique_ptr<asp_grid> handle(new asp_grid);
    handle->grid = asp::Grid::create(dimension, nx, ny, lx, ly);
    *out = handle.release();
  });
}
}  // namespace

extern "C" {

int asp_grid_create_1d(int64_t nx, double lx, asp_grid **out) {
  return create_grid("asp_grid_create_1d", 1, nx, 1, lx, 1.0, out);
}

int asp_grid_create_2d(int64_t nx, int64_t ny, double lx, double ly, asp_grid **out) {
  return create_grid("asp_grid_create_2d", 2, nx, ny, lx, ly, out);
}

// Drops the caller's reference; systems made on the grid keep their own.
void asp_grid_destroy(asp_grid *grid) { delete grid; }

int asp_grid_get_shape(const asp_grid *grid, int *dimension, int64_t *nx, int64_t *ny,
                       int64_t *n_pixels) {
  return guarded("asp_grid_get_shape", [&] {
    asp::require_not_null(grid, "grid");
    const asp::Grid &g = *grid->grid;
    if (dimension) *dimension = g.dimension();
    if (nx) *nx = g.nx();
    if (ny) *ny = g.ny();
    if (n_pixels) *n_pixels = g.n_pixels();
  });
}

int asp_grid_get_box(const asp_grid *grid, double *lx, double *ly) {
  return guarded("asp_grid_get_box", [&] {
    asp::require_not_null(grid, "grid");
    if (lx) *lx = grid->grid->lx();
    if (ly) *ly = grid->grid->ly();
  });
}

int asp_grid_set_fft_planning(asp_grid *grid, int planning) {
  return guarded("asp_grid_set_fft_planning", [&] {
    asp::require_not_null(grid, "grid");
    asp::capi::require_member(planning, asp::capi::Family::planning, "planning");
    grid->grid->set_fft_planning(planning == ASP_FFT_PATIENT   ? asp::FftPlanning::patient
                                 : planning == ASP_FFT_MEASURE ? asp::FftPlanning::measure
                                                               : asp::FftPlanning::estimate);
  });
}

int asp_grid_set_threads(asp_grid *grid, int threads) {
  return guarded("asp_grid_set_threads", [&] {
    asp::require_not_null(grid, "grid");
    grid->grid->set_threads(threads);
  });
}

int asp_grid_get_threads(const asp_grid *grid, int *threads) {
  return guarded("asp_grid_get_threads", [&] {
    asp::require_not_null(grid, "grid");
    asp::require_not_null(threads, "threads");
    *threads = grid->grid->threads();
  });
}

int asp_grid_get_slab(const asp_grid *grid, int64_t *local_ny, int64_t *row_offset,
                      int64_t *local_pixels) {
  return guarded("asp_grid_get_slab", [&] {
    asp::require_not_null(grid, "grid");
    const asp::Grid &g = *grid->grid;
    if (local_ny) *local_ny = g.local_rows();
    if (row_offset) *row_offset = g.row_offset();
    if (local_pixels) *local_pixels = g.local_pixels();
  });
}

int asp_fft_export_wisdom(const char *path) {
  return guarded("asp_fft_export_wisdom", [&] {
    asp::require_not_null(path, "path");
    asp::export_fft_wisdom(path);
  });
}

int asp_fft_import_wisdom(const char *path) {
  return guarded("asp_fft_import_wisdom", [&] {
    asp::require_not_null(path, "path");
    asp::import_fft_wisdom(path);
  });
}

}  // extern "C"
