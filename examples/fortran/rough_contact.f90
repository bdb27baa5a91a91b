! SPDX-License-Identifier: GPL-2.0-or-later
! The C example's scene from Fortran: a self-affine rough surface pressed onto an elastic
! half-space, solved with Polonsky & Keer's method. Plain Fortran strings, default integers
! for the sizes, the seed and the counts, and the fields as h(nx, ny) arrays.
program rough_contact
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_null_ptr
  use asperity
  implicit none

  integer, parameter :: n = 128
  real(c_double), parameter :: length = 1.0d0, modulus = 1.0d0, rms_slope = 0.1d0
  real(c_double), parameter :: mean_pressure = 0.002d0
  type(c_ptr) :: grid = c_null_ptr, system = c_null_ptr, solver = c_null_ptr
  real(c_double), allocatable :: heights(:, :), pressure(:, :)
  real(c_double) :: fraction, penetration, error, mean_error
  integer(c_int64_t) :: iterations
  integer(c_int) :: converged, k0_status

  allocate (heights(n, n), pressure(n, n))   ! h(i, j): x fastest, as asperity stores it
  call check(asp_grid_create_2d(n, n, length, length, grid))
  call check(asp_topography_self_affine(grid, 0.8d0, length, length / 4, 4 * length / n, &
                                        ASP_RMS_SLOPE, rms_slope, 42, heights, size(heights)))
  call check(asp_system_create(grid, modulus, system))
  call check(asp_system_set_topography(system, heights, size(heights)))
  call check(asp_solver_create('pk', solver))
  call check(asp_solver_set_max_iterations(solver, 1000))
  call check(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure))

  call check(asp_system_get(system, ASP_CONTACT_FRACTION, fraction))
  call check(asp_system_get(system, ASP_PENETRATION, penetration))
  call check(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, size(pressure)))
  call check(asp_solver_iterations(solver, iterations))
  call check(asp_solver_final_error(solver, error))
  call check(asp_solver_converged(solver, converged))

  print '(a, a)', 'asperity ', asp_version_text()
  print '(a, f8.5, a, es10.3)', 'contact fraction ', fraction, ' at mean pressure ', mean_pressure
  print '(a, es12.5, a, i0, a, es9.2)', 'penetration ', penetration, ', iterations ', &
      iterations, ', error ', error
  print '(a, es12.5)', 'mean of the pressure field ', sum(pressure) / size(pressure)

  ! A bad argument is reported, not fatal: the status and the message say what was wrong.
  k0_status = asp_system_set_k0(system, -1.0d0)
  print '(a, a)', 'expected error: ', asp_last_error_text()
  mean_error = abs(sum(pressure) / size(pressure) - mean_pressure)

  call release()
  if (converged /= 1) error stop 'the solve did not converge'
  if (k0_status /= ASP_ERR_INVALID_ARGUMENT) error stop 'a negative K0 was not refused'
  if (mean_error > 1d-12 * mean_pressure) error stop 'the mean pressure is not the one asked for'

contains

  subroutine check(status)
    integer(c_int), intent(in) :: status
    if (status /= ASP_OK) then
      print '(a, a)', 'asperity error: ', asp_last_error_text()
      call release()
      error stop 1
    end if
  end subroutine

  ! Gives back the handles and the arrays, on every way out. The destroy functions accept
  ! NULL, so this works at any point.
  subroutine release()
    call asp_solver_destroy(solver)
    call asp_system_destroy(system)
    call asp_grid_destroy(grid)
    solver = c_null_ptr
    system = c_null_ptr
    grid = c_null_ptr
    if (allocated(heights)) deallocate (heights)
    if (allocated(pressure)) deallocate (pressure)
  end subroutine

end program rough_contact
