! SPDX-License-Identifier: GPL-2.0-or-later
! A potential written in Fortran: the exponential soft wall
!   phi(g) = gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a)
! as a bind(c) function handed to asp_system_set_potential with c_funloc, its parameters
! reaching it through the user-data pointer. A sphere is pressed onto it and solved by the
! preconditioned L-BFGS ("lbfgs_fourier"); the same scene with the library's own soft wall
! (asp_system_set_soft_wall) must give the same solution.
module soft_wall_potential
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_associated, &
                                         c_f_pointer
  implicit none
  private
  public :: soft_wall, evaluate

  ! The wall's parameters, and the number of times the solver asked for the potential.
  type, bind(c) :: soft_wall
    real(c_double) :: gamma_r, rho_r, gamma_a, rho_a
    integer(c_int64_t) :: calls = 0
  end type

  ! Where an exponent exp(x) reaches x = 40 it is continued by its quadratic Taylor expansion,
  ! as the library's wall is, so that deep interpenetration costs a finite energy.
  real(c_double), parameter :: largest_exponent = 40

contains

  ! An asp_potential_fn: phi, phi' and (when asked) phi'' at the n gaps.
  function evaluate(n, gap, phi, dphi, d2phi, user_data) result(status) bind(c)
    integer(c_int64_t), value :: n
    real(c_double), intent(in) :: gap(n)
    real(c_double), intent(out) :: phi(n), dphi(n)
    type(c_ptr), value :: d2phi, user_data
    integer(c_int) :: status
    type(soft_wall), pointer :: wall
    real(c_double), pointer :: curvature(:)
    real(c_double) :: r(3), a(3)
    integer(c_int64_t) :: i
    call c_f_pointer(user_data, wall)
    wall%calls = wall%calls + 1
    if (c_associated(d2phi)) call c_f_pointer(d2phi, curvature, [n])
    do i = 1, n
      r = exponential(wall%gamma_r, wall%rho_r / 2, gap(i))   ! the repulsion
      a = exponential(wall%gamma_a, wall%rho_a, gap(i))       ! the attraction
      phi(i) = r(1) - a(1)
      dphi(i) = r(2) - a(2)
      if (c_associated(d2phi)) curvature(i) = r(3) - a(3)
    end do
    status = 0
  end function

  ! strength exp(-g/range), its first and second derivatives in g, continued quadratically
  ! below g = -largest_exponent range.
  pure function exponential(strength, range, g) result(f)
    real(c_double), intent(in) :: strength, range, g
    real(c_double) :: f(3), g0, f0, step
    g0 = -largest_exponent * range
    if (g >= g0) then
      f(1) = strength * exp(-g / range)
      f(2) = -f(1) / range
      f(3) = f(1) / range**2
    else
      f0 = strength * exp(largest_exponent)
      step = g - g0
      f(1) = f0 * (1 - step / range + step**2 / (2 * range**2))
      f(2) = f0 * (-1 / range + step / range**2)
      f(3) = f0 / range**2
    end if
  end function

end module soft_wall_potential

program user_potential
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_null_ptr, c_funloc, c_loc
  use asperity
  use soft_wall_potential
  implicit none

  integer, parameter :: n = 64
  real(c_double), parameter :: modulus = 1, radius = 1, mean_pressure = 1d-3
  type(c_ptr) :: grid = c_null_ptr, system = c_null_ptr, solver = c_null_ptr
  type(soft_wall), target :: wall
  real(c_double) :: heights(n, n), pressure(n, n), reference(n, n)
  real(c_double) :: gap_user, gap_builtin, energy_user, energy_builtin, difference

  wall = soft_wall(1d-4, 2d-3, 5d-5, 2d-3)
  call check(asp_grid_create_2d(n, n, 1d0, 1d0, grid))
  call check(asp_topography_sphere(grid, radius, heights, size(heights)))
  call check(asp_system_create(grid, modulus, system))
  call check(asp_system_set_topography(system, heights, size(heights)))
  call check(asp_solver_create('lbfgs_fourier', solver))
  call check(asp_solver_set_tolerance(solver, 1d-12))

  ! The wall written in Fortran, without the hard wall.
  call check(asp_system_set_potential(system, c_funloc(evaluate), c_loc(wall), 0))
  call solve(pressure, gap_user, energy_user)
  print '(a, i0, a)', 'Fortran soft wall: ', wall%calls, ' evaluations of the potential'
  print '(a, es22.15, a, es22.15)', '  mean gap ', gap_user, ', interaction energy ', energy_user

  ! The library's own wall with the same parameters, from the same cold start.
  call check(asp_system_set_soft_wall(system, wall%gamma_r, wall%rho_r, wall%gamma_a, &
                                      wall%rho_a))
  call check(asp_system_reset(system))
  call solve(reference, gap_builtin, energy_builtin)
  print '(a)', 'built-in soft wall:'
  print '(a, es22.15, a, es22.15)', '  mean gap ', gap_builtin, ', interaction energy ', &
      energy_builtin

  difference = maxval(abs(pressure - reference)) / maxval(abs(reference))
  print '(a, es9.2)', 'largest pressure difference, relative to the largest pressure: ', &
      difference
  call release()
  if (wall%calls == 0) error stop 'the Fortran potential was never called'
  if (difference > 1d-10) error stop 'the pressures differ'
  if (abs(gap_user - gap_builtin) > 1d-10 * abs(gap_builtin)) error stop 'the mean gaps differ'
  if (abs(energy_user - energy_builtin) > 1d-10 * abs(energy_builtin)) &
    error stop 'the interaction energies differ'

contains

  subroutine solve(field, mean_gap, interaction_energy)
    real(c_double), intent(out) :: field(n, n), mean_gap, interaction_energy
    integer(c_int) :: converged
    call check(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure))
    call check(asp_solver_converged(solver, converged))
    if (converged /= 1) then
      call release()
      error stop 'a solve did not converge'
    end if
    call check(asp_system_get_field(system, ASP_FIELD_PRESSURE, field, size(field)))
    call check(asp_system_get(system, ASP_MEAN_GAP, mean_gap))
    call check(asp_system_get(system, ASP_INTERACTION_ENERGY, interaction_energy))
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

end program user_potential
