! SPDX-License-Identifier: GPL-2.0-or-later
! The solver's report by key through the Fortran module (asp_solver_get): refused before a
! solve; after a converged solve with a history and one at the iteration limit without, every
! ASP_REPORT_* key gives what the getter of its own gives (the counts as exact doubles); a key
! of another family and a key of no family refused, naming the argument. Prints every failed
! check and exits non-zero if there was one.
program test_solver_report
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr
  use asperity
  implicit none
  integer, parameter :: n = 16
  type(c_ptr) :: grid, system, solver
  real(c_double) :: h(n, n), value
  integer :: failures = 0

  call expect_status(asp_grid_create_2d(n, n, 1d0, 1d0, grid), ASP_OK, 'asp_grid_create_2d')
  call expect_status(asp_topography_sinusoid(grid, 0.01d0, 1, 1, h, size(h)), ASP_OK, &
                     'asp_topography_sinusoid')
  call expect_status(asp_system_create(grid, 1d0, system), ASP_OK, 'asp_system_create')
  call expect_status(asp_system_set_topography(system, h, size(h)), ASP_OK, &
                     'asp_system_set_topography')
  call expect_status(asp_solver_create('pk', solver), ASP_OK, 'asp_solver_create')

  value = -1
  call expect_status(asp_solver_get(solver, ASP_REPORT_ITERATIONS, value), &
                     ASP_ERR_INVALID_STATE, 'asp_solver_get before a solve')
  call expect(value == -1, 'a refused call leaves the value alone')

  call expect_status(asp_solver_set_history(solver, 1_c_int), ASP_OK, 'asp_solver_set_history')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 1d-3), ASP_OK, &
                     'the converged solve')
  call check_keys_agree('a converged solve with a history', ASP_TERMINATION_CONVERGED)

  call expect_status(asp_solver_set_history(solver, 0_c_int), ASP_OK, 'asp_solver_set_history')
  call expect_status(asp_solver_set_max_iterations(solver, 1), ASP_OK, &
                     'asp_solver_set_max_iterations')
  call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 1d-3), ASP_OK, &
                     'the solve at the iteration limit')
  call check_keys_agree('a solve at the iteration limit', ASP_TERMINATION_ITERATION_LIMIT)

  call expect_status(asp_solver_get(solver, ASP_HISTORY_ITERATION, value), &
                     ASP_ERR_INVALID_ARGUMENT, 'a history column as a report key')
  call expect(index(asp_last_error_text(), 'ASP_HISTORY_ITERATION') > 0, &
              'the message names the constant of the other family')
  call expect_status(asp_solver_get(solver, 42_c_int, value), ASP_ERR_INVALID_ARGUMENT, &
                     'a key of no family')
  call expect(index(asp_last_error_text(), "'key'") > 0, 'the message names the argument')

  call asp_solver_destroy(solver)
  call asp_system_destroy(system)
  call asp_grid_destroy(grid)
  if (failures > 0) then
    print '(i0, a)', failures, ' checks failed'
    error stop 1
  end if
  print '(a)', 'test_solver_report: all checks passed'

contains

  subroutine check_keys_agree(what, expected_reason)
    character(len=*), intent(in) :: what
    integer(c_int), intent(in) :: expected_reason
    integer(c_int) :: reason, converged
    integer(c_int64_t) :: iterations, evaluations, transforms, rows
    real(c_double) :: error, seconds
    call expect_status(asp_solver_termination(solver, reason), ASP_OK, what)
    call expect(reason == expected_reason, what // ': the termination reason')
    call expect_status(asp_solver_get(solver, ASP_REPORT_TERMINATION, value), ASP_OK, what)
    call expect(int(value, c_int) == reason, what // ': ASP_REPORT_TERMINATION')
    call expect_status(asp_solver_converged(solver, converged), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_CONVERGED, value), ASP_OK, what)
    call expect(int(value, c_int) == converged, what // ': ASP_REPORT_CONVERGED')
    call expect_status(asp_solver_iterations(solver, iterations), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_ITERATIONS, value), ASP_OK, what)
    call expect(int(value, c_int64_t) == iterations .and. iterations > 0, &
                what // ': ASP_REPORT_ITERATIONS')
    call expect_status(asp_solver_evaluations(solver, evaluations), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_EVALUATIONS, value), ASP_OK, what)
    call expect(int(value, c_int64_t) == evaluations, what // ': ASP_REPORT_EVALUATIONS')
    call expect_status(asp_solver_transforms(solver, transforms), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_TRANSFORMS, value), ASP_OK, what)
    call expect(int(value, c_int64_t) == transforms, what // ': ASP_REPORT_TRANSFORMS')
    call expect_status(asp_solver_final_error(solver, error), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_FINAL_ERROR, value), ASP_OK, what)
    call expect(value == error, what // ': ASP_REPORT_FINAL_ERROR')
    call expect_status(asp_solver_elapsed_seconds(solver, seconds), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_ELAPSED_SECONDS, value), ASP_OK, what)
    call expect(value == seconds, what // ': ASP_REPORT_ELAPSED_SECONDS')
    call expect_status(asp_solver_history_length(solver, rows), ASP_OK, what)
    call expect_status(asp_solver_get(solver, ASP_REPORT_HISTORY_LENGTH, value), ASP_OK, what)
    call expect(int(value, c_int64_t) == rows, what // ': ASP_REPORT_HISTORY_LENGTH')
  end subroutine

  subroutine expect(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (.not. condition) then
      failures = failures + 1
      print '(2a)', 'check failed: ', what
    end if
  end subroutine

  subroutine expect_status(status, expected, what)
    integer(c_int), intent(in) :: status, expected
    character(len=*), intent(in) :: what
    if (status /= expected) then
      failures = failures + 1
      print '(a, i0, a, i0, 4a)', 'status ', status, ' (want ', expected, ') from ', what, &
                                  ': ', asp_last_error_text()
    end if
  end subroutine

end program
