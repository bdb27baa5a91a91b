! SPDX-License-Identifier: GPL-2.0-or-later
! A load-unload sweep with the adhesive hard wall: the double sinewave of the thesis's Table 5
! (1D, E* = 1/pi, a long wave of amplitude 1 and 32 ripples of amplitude 0.05) on 512 points,
! w = 0.03 and range 0.0153, solved by L-BFGS-B on the gap under penetration control. Each
! step starts from the solution of the previous one. The ripples jump into contact on loading
! and come out of it only later on unloading, so the unloading curve lies below the loading
! curve: the program checks that hysteresis, and that every step converged.
program adhesive_sweep
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_null_ptr
  use asperity
  implicit none

  integer, parameter :: n = 512, steps = 22
  real(c_double), parameter :: pi = 3.14159265358979323846d0
  real(c_double), parameter :: first = -0.04d0, last = 0.4d0
  type(c_ptr) :: grid = c_null_ptr, system = c_null_ptr, solver = c_null_ptr
  real(c_double) :: heights(n), penetration(0:steps), loading(0:steps), unloading(0:steps)
  real(c_double) :: largest_gap
  integer(c_int64_t) :: iterations
  integer(c_int) :: converged
  integer :: k, worst

  call check(asp_grid_create_1d(n, 1d0, grid))
  call check(asp_topography_double_sinewave(grid, 1d0, 0.05d0, 32, heights, size(heights)))
  call check(asp_system_create(grid, 1 / pi, system))
  call check(asp_system_set_topography(system, heights, size(heights)))
  call check(asp_system_set_adhesion(system, 0.03d0, 0.0153d0))
  call check(asp_solver_create('lbfgsb', solver))
  call check(asp_solver_set_option_string(solver, 'variable', 'gap'))
  call check(asp_solver_set_tolerance(solver, 1d-8))

  penetration = [(first + (last - first) * k / steps, k = 0, steps)]
  print '(a)', '   penetration   mean pressure   iterations'
  do k = 0, steps
    call solve_at(penetration(k), loading(k))
  end do
  do k = steps, 0, -1
    call solve_at(penetration(k), unloading(k))
  end do

  ! Hysteresis: somewhere the unloading pressure lies clearly below the loading pressure (the
  ! ripples still stuck), and at the deepest point, where both are the same step, they agree.
  largest_gap = maxval(loading - unloading)
  worst = maxloc(loading - unloading, dim=1) - 1
  print '(a, es10.3, a, f7.4)', 'largest loading - unloading difference ', largest_gap, &
      ' at penetration ', penetration(worst)
  call release()
  if (abs(loading(steps) - unloading(steps)) > 1d-6 * abs(loading(steps))) &
    error stop 'the turning point differs between loading and unloading'
  if (largest_gap <= 1d-3 * maxval(abs(loading))) error stop 'no hysteresis'
  if (any(unloading > loading + 1d-6 * maxval(abs(loading)))) &
    error stop 'unloading lies above loading'

contains

  subroutine solve_at(delta, mean_pressure)
    real(c_double), intent(in) :: delta
    real(c_double), intent(out) :: mean_pressure
    call check(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, delta))
    call check(asp_solver_converged(solver, converged))
    call check(asp_solver_iterations(solver, iterations))
    call check(asp_system_get(system, ASP_MEAN_PRESSURE, mean_pressure))
    print '(f14.4, es16.6, i13)', delta, mean_pressure, iterations
    if (converged /= 1) then
      call release()
      error stop 'a step did not converge'
    end if
  end subroutine

  subroutine check(status)
    integer(c_int), intent(in) :: status
    if (status /= ASP_OK) then
      print '(a, a)', 'asperity error: ', asp_last_error_text()
      call release()
      error stop 1
    end if
  end subroutine

  subroutine release()
    call asp_solver_destroy(solver)
    call asp_system_destroy(system)
    call asp_grid_destroy(grid)
    solver = c_null_ptr
    system = c_null_ptr
    grid = c_null_ptr
  end subroutine

end program adhesive_sweep
