! SPDX-License-Identifier: GPL-2.0-or-later
! A rough adhesive contact in series with an elastic spring, as a finite-element code couples
! it (the Fortran twin of examples/c/fem_coupling.c): a spring of stiffness k (force per
! length) pulled at its far end to the displacement D presses a rough surface (64 x 64) onto
! the half-space with the penetration delta, and equilibrium is
!   R(delta) = k (D - delta) - F(delta) = 0,   F = A pbar, the contact force.
! Each load step solves it by Newton's method on delta with the consistent tangent
! dR/d(delta) = -k - A d(pbar)/d(delta) from asp_solver_normal_stiffness, each contact solve
! warm-started from the last, and prints the residual of every Newton step (it falls
! quadratically). One step is done again with a finite-difference tangent to compare. Stops
! with an error if a solve does not converge or Newton needs more than 6 steps (it takes 3).
program fem_coupling
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_null_ptr
  use asperity
  implicit none

  integer, parameter :: n = 64, max_newton = 6
  real(c_double), parameter :: length = 1, modulus = 1, work = 1d-5, range = 2d-3
  real(c_double), parameter :: spring = 0.05d0, area = length * length
  type(c_ptr) :: grid = c_null_ptr, system = c_null_ptr, solver = c_null_ptr
  real(c_double) :: heights(n, n), height_range, delta, d, tolerance, saved, converged_delta
  integer :: step, steps, solves

  call check(asp_grid_create_2d(n, n, length, length, grid))
  call check(asp_topography_self_affine(grid, 0.8d0, length, length / 4, 4 * length / n, &
                                        ASP_RMS_SLOPE, 0.1d0, 42, heights, size(heights)))
  height_range = maxval(heights) - minval(heights)
  call check(asp_system_create(grid, modulus, system))
  call check(asp_system_set_topography(system, heights, size(heights)))
  call check(asp_system_set_adhesion(system, work, range))
  call check(asp_solver_create('bugnicourt', solver))
  call check(asp_solver_set_option_string(solver, 'variable', 'gap'))
  call check(asp_solver_set_tolerance(solver, 1d-12))

  ! The residual is met to 1e-9 of the largest spring force, well above the solves' error.
  tolerance = 1d-9 * spring * height_range
  print '(a, f5.2, a)', 'spring k = ', spring, ' in series with a rough adhesive contact (64 x 64)'
  delta = 0
  do step = 1, 5
    d = 0.15d0 * step * height_range
    print '(a, i0, a, f10.6)', 'load step ', step, ': D = ', d
    ! Each step starts from the last one's delta; the first from D, as if the contact were
    ! rigid (at delta = 0 only the top pixel touches, and adhesion makes F fall with delta
    ! there: a poor place to start Newton).
    if (step == 1) delta = d
    saved = delta
    solves = 0
    call newton(d, .false., 0d0, delta, steps, solves)
    print '(a, i0, a, i0, a)', '  consistent tangent: ', steps, ' Newton steps, ', solves, &
        ' contact solves'
    if (step == 3) then
      converged_delta = delta
      delta = saved
      solves = 0
      print '(a)', '  the same with a finite-difference tangent (h = 1e-6 of the height range):'
      call newton(d, .true., 1d-6 * height_range, delta, steps, solves)
      print '(a, i0, a, i0, a)', '  finite-difference tangent: ', steps, ' Newton steps, ', &
          solves, ' contact solves'
      if (abs(delta - converged_delta) > 1d-8 * height_range) then
        call release()
        error stop 'the two tangents found different equilibria'
      end if
    end if
  end do
  call release()

contains

  ! Newton's method on delta for the spring pulled to d, from delta; finite_difference: the
  ! tangent from central differences of two more solves at delta +- h.
  subroutine newton(d, finite_difference, h, delta, steps, solves)
    real(c_double), intent(in) :: d, h
    logical, intent(in) :: finite_difference
    real(c_double), intent(inout) :: delta
    integer, intent(out) :: steps
    integer, intent(inout) :: solves
    real(c_double) :: force, tangent, residual, up, down
    do steps = 0, max_newton
      if (finite_difference) then
        call contact(delta + h, up)
        call contact(delta - h, down)
        tangent = (up - down) / (2 * h)
        solves = solves + 2
        call contact(delta, force)
      else
        call contact(delta, force, tangent)
      end if
      solves = solves + 1
      residual = spring * (d - delta) - force
      print '(a, i0, a, f15.12, a, es10.3)', '    Newton step ', steps, ': delta ', delta, &
          '  residual ', residual
      if (abs(residual) <= tolerance) return
      delta = delta - residual / (-spring - tangent)
    end do
    call release()
    error stop 'Newton did not converge in 6 steps'
  end subroutine

  ! The contact force at delta (a warm-started solve) and, if asked, the tangent A dpbar/ddelta.
  subroutine contact(delta, force, tangent)
    real(c_double), intent(in) :: delta
    real(c_double), intent(out) :: force
    real(c_double), intent(out), optional :: tangent
    real(c_double) :: pbar, stiffness
    integer(c_int) :: converged
    call check(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, delta))
    call check(asp_solver_converged(solver, converged))
    if (converged /= 1) then
      call release()
      error stop 'a contact solve did not converge'
    end if
    call check(asp_system_get(system, ASP_MEAN_PRESSURE, pbar))
    force = area * pbar
    if (present(tangent)) then
      call check(asp_solver_normal_stiffness(solver, system, stiffness))
      tangent = area * stiffness
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

end program fem_coupling
