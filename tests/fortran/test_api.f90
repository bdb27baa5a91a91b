! SPDX-License-Identifier: GPL-2.0-or-later
! The public interface through the Fortran module: a Hertzian sphere solved with "pk", options
! set by name (and refused by name), the history, a progress callback written in Fortran that
! cancels the solve, a solve to convergence, the texts that come back in buffers, FFTW wisdom,
! the scalar results, a free (non-periodic) half-space, and the soft potentials (the soft wall,
! the Lennard-Jones wall, a potential written in Fortran as a bind(c) callback, the hard wall
! back), and the module's generic interfaces (strings without c_null_char, default-integer
! counts, seeds and sizes, fields of rank 1 and 2). Prints every failed check and exits non-zero if there was one.
module api_checks
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_f_pointer, &
                                         c_associated
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use asperity
  implicit none
  private
  public :: progress_counter, count_and_cancel, soft_wall, soft_wall_potential, expect, &
            expect_status, failures

  ! What the progress callback sees through its user data.
  type, bind(c) :: progress_counter
    integer(c_int64_t) :: calls = 0          ! calls so far
    integer(c_int64_t) :: cancel_after = -1  ! return non-zero on this call (< 0: never)
    integer(c_int64_t) :: out_of_order = 0   ! calls whose iteration was not calls - 1
    integer(c_int64_t) :: bad_values = 0     ! calls with negative or decreasing seconds, or
                                             ! a non-finite or negative error
    real(c_double) :: last_seconds = 0
  end type

  ! The parameters of asp_system_set_soft_wall, for a potential that computes it, and its
  ! calls so far.
  type, bind(c) :: soft_wall
    real(c_double) :: gamma_r, rho_r, gamma_a, rho_a
    integer(c_int64_t) :: calls = 0
  end type

  integer :: failures = 0

contains

  ! An asp_progress_fn: counts its calls in the progress_counter that user_data points to,
  ! checks what it is given, and cancels on the call the counter asks for.
  function count_and_cancel(iteration, seconds, error, user_data) result(cancel) bind(c)
    integer(c_int64_t), value :: iteration
    real(c_double), value :: seconds, error
    type(c_ptr), value :: user_data
    integer(c_int) :: cancel
    type(progress_counter), pointer :: counter
    call c_f_pointer(user_data, counter)
    if (iteration /= counter%calls) counter%out_of_order = counter%out_of_order + 1
    if (seconds < 0 .or. seconds < counter%last_seconds .or. .not. ieee_is_finite(error) &
        .or. error < 0) counter%bad_values = counter%bad_values + 1
    counter%last_seconds = seconds
    counter%calls = counter%calls + 1
    cancel = 0
    if (counter%calls == counter%cancel_after) cancel = 1
  end function

  ! An asp_potential_fn: the soft wall gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a) of the
  ! soft_wall that user_data points to (above its continuation thresholds: the tests' gaps are
  ! not negative).
  function soft_wall_potential(n, gap, phi, dphi, d2phi, user_data) result(status) bind(c)
    integer(c_int64_t), value :: n
    real(c_double), intent(in) :: gap(n)
    real(c_double), intent(out) :: phi(n), dphi(n)
    type(c_ptr), value :: d2phi, user_data
    integer(c_int) :: status
    type(soft_wall), pointer :: wall
    real(c_double), pointer :: curvature(:)
    real(c_double) :: repulsion(n), attraction(n)
    call c_f_pointer(user_data, wall)
    wall%calls = wall%calls + 1
    repulsion = wall%gamma_r * exp(-2 * gap / wall%rho_r)
    attraction = wall%gamma_a * exp(-gap / wall%rho_a)
    phi = repulsion - attraction
    dphi = -2 * repulsion / wall%rho_r + attraction / wall%rho_a
    if (c_associated(d2phi)) then
      call c_f_pointer(d2phi, curvature, [n])
      curvature = 4 * repulsion / wall%rho_r**2 - attraction / wall%rho_a**2
    end if
    status = 0
  end function

  subroutine expect(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (.not. condition) then
      failures = failures + 1
      print '(a, a)', 'FAILED: ', what
    end if
  end subroutine

  ! status must be expected; on a mismatch the library's message is printed too.
  subroutine expect_status(status, expected, what)
    integer(c_int), intent(in) :: status, expected
    character(len=*), intent(in) :: what
    if (status /= expected) then
      failures = failures + 1
      print '(a, a, a, i0, a, i0, a, a)', 'FAILED: ', what, ': status ', status, &
          ' instead of ', expected, '; last error: ', asp_last_error_text()
    end if
  end subroutine

end module api_checks

program test_api
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_null_ptr, &
                                         c_null_funptr, c_null_char, c_associated, c_funloc, &
                                         c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use asperity
  use api_checks
  implicit none

  integer(c_int64_t), parameter :: n = 64, cancel_after = 3
  real(c_double), parameter :: box = 1, modulus = 1, radius = 1, mean_pressure = 1d-3
  real(c_double), parameter :: tolerance = 1d-10
  character(len=*), parameter :: wisdom_file = 'fortran_api.wisdom'
  character(len=18), parameter :: unconstrained(5) = [character(len=18) :: 'lbfgs', &
      'lbfgs_fourier', 'gfmd', 'fire', 'fire_mass_weighted']

  type(c_ptr) :: grid, system, solver, no_solver, adhesive_solver, free_system, line, no_system, &
                 lbfgsb, soft_solver, layer_system
  type(progress_counter), target :: counter
  type(soft_wall), target :: wall
  real(c_double), allocatable :: heights(:, :), pressure(:, :), column(:)
  real(c_double), allocatable :: seconds(:), errors(:), evaluations(:), transforms(:)
  character(len=:), allocatable :: text, names
  character(len=2) :: small
  character(len=256) :: large
  character(len=1024) :: sentence
  character(len=32) :: padded_name
  integer(c_int64_t) :: length, rows, iterations, count, nx, ny, pixels, i
  integer(c_int) :: status, reason, converged, dimension
  real(c_double) :: value, error, scalar, lx, ly, penetration, expected_ratio, stiffness
  integer(c_int) :: flag
  integer :: k, unit
  ! For the generic interfaces: default integers, a rank-1 field, a string with its NUL.
  integer, parameter :: m = 32
  type(c_ptr) :: small_grid, small_system, plain_solver
  real(c_double) :: field(m, m), line_field(m * m), q(8), c(8)
  real(c_double) :: rms_height, rms_slope, rms_curvature
  character(len=64) :: option_text

  allocate (heights(n, n), pressure(n, n))

  ! ---- version and status texts ----
  call expect(len(asp_version_text()) > 0, 'asp_version_text is not empty')
  call expect(asp_abi_version() >= 1, 'asp_abi_version is at least 1')
  call expect(len(asp_status_text(ASP_ERR_IO)) > 0 .and. &
              asp_status_text(ASP_ERR_IO) /= asp_status_text(ASP_OK), &
              'asp_status_text(ASP_ERR_IO) has a text of its own')

  ! ---- grid, a sphere, a system ----
  call expect_status(asp_grid_create_2d(n, n, box, box, grid), ASP_OK, 'asp_grid_create_2d')
  call expect_status(asp_grid_get_shape(grid, dimension, nx, ny, pixels), ASP_OK, &
                     'asp_grid_get_shape')
  call expect(dimension == 2 .and. nx == n .and. ny == n .and. pixels == n * n, &
              'the grid has the shape it was made with')
  call expect_status(asp_grid_get_box(grid, lx, ly), ASP_OK, 'asp_grid_get_box')
  call expect(lx == box .and. ly == box, 'the grid has the box it was made with')
  call expect_status(asp_topography_sphere(grid, radius, heights, n * n), ASP_OK, &
                     'asp_topography_sphere')
  call expect(maxval(heights) == 0, 'the apex of the sphere is at h = 0')
  call expect_status(asp_system_create(grid, modulus, system), ASP_OK, 'asp_system_create')
  call expect_status(asp_system_set_topography(system, heights, n * n), ASP_OK, &
                     'asp_system_set_topography')
  call expect_status(asp_system_set_topography(system, heights, n * n - 1), &
                     ASP_ERR_SIZE_MISMATCH, 'asp_system_set_topography with a wrong count')

  ! ---- algorithms and the solver's description, as texts and in buffers ----
  names = asp_algorithms_text(status)
  call expect_status(status, ASP_OK, 'asp_algorithms_text')
  call expect(index(names, 'pk' // new_line('a')) == 1, &
              'the algorithms start with "pk" on a line of its own: "' // names // '"')
  status = asp_algorithms(large, len(large, c_int64_t), length)
  call expect_status(status, ASP_OK, 'asp_algorithms into a large buffer')
  call expect(length == len(names, c_int64_t), 'asp_algorithms reports the length of the text')
  call expect(large(1:len(names)) == names .and. large(len(names) + 1:len(names) + 1) == &
              c_null_char, 'asp_algorithms writes the text and its NUL into the buffer')
  status = asp_algorithms(small, len(small, c_int64_t), length)
  call expect_status(status, ASP_ERR_SIZE_MISMATCH, 'asp_algorithms into a 2-byte buffer')
  call expect(length == len(names, c_int64_t), &
              'asp_algorithms reports the full length even when the buffer is too small')
  call expect(small(1:1) == names(1:1) .and. small(2:2) == c_null_char, &
              'a buffer too small receives the text cut to size - 1 characters and a NUL')

  call expect_status(asp_solver_create('no_such_algorithm', no_solver), ASP_ERR_UNSUPPORTED, &
                     'asp_solver_create with an unknown algorithm')
  call expect(.not. c_associated(no_solver), 'a failed create sets the handle to NULL')
  call expect(index(asp_last_error_text(), 'no_such_algorithm') > 0, &
              'the message names the unknown algorithm: ' // asp_last_error_text())
  ! Trailing blanks, as a fixed-length Fortran variable has, are dropped.
  call expect_status(asp_solver_create('pk  ', solver), ASP_OK, &
                     'asp_solver_create with a blank-padded name')

  text = asp_solver_describe_text(solver, status)
  call expect_status(status, ASP_OK, 'asp_solver_describe_text')
  call expect(index(text, 'pk') == 1, 'the description starts with the name')
  call expect(index(text, 'tolerance') > 0 .and. index(text, 'max_iterations') > 0 .and. &
              index(text, 'stall_window') > 0, 'the description lists the common options')
  status = asp_solver_describe(solver, large, 0_c_int64_t, length)
  call expect_status(status, ASP_OK, 'asp_solver_describe asking for the length')
  call expect(length == len(text, c_int64_t), 'asp_solver_describe reports the length')

  ! ---- options by name ----
  call expect_status(asp_solver_get_option(solver, 'tolerance', value), ASP_OK, &
                     'asp_solver_get_option(tolerance)')
  call expect(value == 1d-8, 'the default tolerance is 1e-8')
  call expect_status(asp_solver_set_option(solver, 'tolerance', tolerance), ASP_OK, &
                     'asp_solver_set_option(tolerance)')
  call expect_status(asp_solver_set_option(solver, 'max_iterations' // c_null_char, 500d0), &
                     ASP_OK, 'asp_solver_set_option(max_iterations)')
  padded_name = 'max_iterations'
  call expect_status(asp_solver_get_option(solver, padded_name, value), ASP_OK, &
                     'asp_solver_get_option with a blank-padded name')
  call expect(value == 500, 'max_iterations reads back as set')

  status = asp_solver_set_option(solver, 'no_such_option', 1d0)
  call expect_status(status, ASP_ERR_INVALID_ARGUMENT, 'an unknown option')
  call expect(index(asp_last_error_text(), 'no_such_option') > 0, &
              'the message names the unknown option: ' // asp_last_error_text())
  call expect(index(asp_last_error_text(), 'tolerance') > 0, &
              'the message lists the valid options: ' // asp_last_error_text())
  status = asp_solver_set_option(solver, 'tolerance', -1d0)
  call expect_status(status, ASP_ERR_INVALID_ARGUMENT, 'a negative tolerance')
  call expect(index(asp_last_error_text(), 'tolerance') > 0, &
              'the message names the option out of range: ' // asp_last_error_text())
  status = asp_solver_set_option(solver, 'max_iterations', 2.5d0)
  call expect_status(status, ASP_ERR_INVALID_ARGUMENT, 'a fractional max_iterations')
  call expect(index(asp_last_error_text(), 'max_iterations') > 0, &
              'the message names the integer option: ' // asp_last_error_text())
  status = asp_solver_set_option_string(solver, 'tolerance', 'tight')
  call expect_status(status, ASP_ERR_INVALID_ARGUMENT, 'a string for a numeric option')
  call expect(index(asp_last_error_text(), 'tolerance') > 0, &
              'the message names the numeric option: ' // asp_last_error_text())
  text = asp_solver_get_option_string_text(solver, 'tolerance', status)
  call expect_status(status, ASP_ERR_INVALID_ARGUMENT, 'reading a numeric option as a string')
  call expect(len(text) == 0, 'a refused text is empty')
  call expect_status(asp_solver_get_option(solver, 'tolerance', value), ASP_OK, &
                     'asp_solver_get_option(tolerance) after refusals')
  call expect(value == tolerance, 'refused values leave the option as it was')

  ! ---- before any solve there is no report ----
  call expect_status(asp_solver_termination(solver, reason), ASP_ERR_INVALID_STATE, &
                     'asp_solver_termination before a solve')

  ! ---- a solve cancelled by the progress callback, with history ----
  counter%cancel_after = cancel_after
  call expect_status(asp_solver_set_history(solver, 1_c_int), ASP_OK, 'asp_solver_set_history')
  call expect_status(asp_solver_set_progress(solver, c_funloc(count_and_cancel), &
                                             c_loc(counter)), ASP_OK, 'asp_solver_set_progress')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_OK, 'the cancelled solve')
  call expect_status(asp_solver_termination(solver, reason), ASP_OK, 'asp_solver_termination')
  call expect(reason == ASP_TERMINATION_CANCELLED, 'the solve ends as cancelled')
  call expect_status(asp_solver_converged(solver, converged), ASP_OK, 'asp_solver_converged')
  call expect(converged == 0, 'a cancelled solve has not converged')
  call expect(counter%calls == cancel_after, 'the callback ran until it cancelled')
  call expect(counter%out_of_order == 0, 'the callback sees iterations 0, 1, 2, ... in order')
  call expect(counter%bad_values == 0, &
              'the callback sees non-decreasing seconds and finite, non-negative errors')
  call expect_status(asp_solver_iterations(solver, iterations), ASP_OK, 'asp_solver_iterations')
  call expect(iterations == cancel_after - 1, 'the cancelled solve stopped at the iteration ' // &
              'of the cancelling call')
  call expect_status(asp_solver_final_error(solver, error), ASP_OK, 'asp_solver_final_error')

  call expect_status(asp_solver_history_length(solver, rows), ASP_OK, &
                     'asp_solver_history_length')
  call expect(rows == cancel_after, 'one history row per iteration, from iteration 0')
  allocate (column(rows), seconds(rows), errors(rows), evaluations(rows), transforms(rows))
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_ITERATION, column, rows), &
                     ASP_OK, 'asp_solver_get_history(ITERATION)')
  call expect(all(column == [(real(i, c_double), i = 0, rows - 1)]), &
              'the iteration column counts 0, 1, 2, ...')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_SECONDS, seconds, rows), &
                     ASP_OK, 'asp_solver_get_history(SECONDS)')
  call expect(seconds(1) >= 0 .and. all(seconds(2:) >= seconds(:rows - 1)), &
              'the seconds column starts non-negative and never decreases')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_ERROR, errors, rows), &
                     ASP_OK, 'asp_solver_get_history(ERROR)')
  call expect(all(ieee_is_finite(errors)) .and. all(errors >= 0), &
              'the error column is finite and non-negative')
  call expect(errors(rows) == error, 'the last error of the history is the final error')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_EVALUATIONS, evaluations, &
                     rows), ASP_OK, 'asp_solver_get_history(EVALUATIONS)')
  call expect(all(evaluations(2:) >= evaluations(:rows - 1)), &
              'the evaluation count never decreases')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_TRANSFORMS, transforms, rows), &
                     ASP_OK, 'asp_solver_get_history(TRANSFORMS)')
  call expect(all(transforms(2:) >= transforms(:rows - 1)) .and. transforms(rows) > 0, &
              'the transform count grows')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_OBJECTIVE, column, rows), &
                     ASP_OK, 'asp_solver_get_history(OBJECTIVE)')
  call expect(all(ieee_is_finite(column)), 'the objective column is finite')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_CONTACT_FRACTION, column, rows), &
                     ASP_OK, 'asp_solver_get_history(CONTACT_FRACTION)')
  call expect(all(column >= 0 .and. column <= 1), 'the contact fraction column is in [0, 1]')
  call expect_status(asp_solver_get_history(solver, ASP_FIELD_GAP, column, rows), &
                     ASP_ERR_INVALID_ARGUMENT, 'a field constant as a history column')
  call expect_status(asp_solver_get_history(solver, ASP_HISTORY_ERROR, column, rows - 1), &
                     ASP_ERR_SIZE_MISMATCH, 'a history column with a wrong count')
  deallocate (column, seconds, errors, evaluations, transforms)
  call expect_status(asp_system_get(system, ASP_MEAN_PRESSURE, scalar), ASP_OK, &
                     'the mean pressure after a cancelled solve')
  call expect(ieee_is_finite(scalar), 'a cancelled solve leaves a finite state')

  ! ---- the same scene, cold, to convergence, without the callback ----
  call expect_status(asp_solver_set_progress(solver, c_null_funptr, c_null_ptr), ASP_OK, &
                     'removing the progress callback')
  call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_OK, 'the solve to convergence')
  call expect_status(asp_solver_termination(solver, reason), ASP_OK, 'asp_solver_termination')
  call expect(reason == ASP_TERMINATION_CONVERGED, 'the solve ends as converged')
  call expect_status(asp_solver_converged(solver, converged), ASP_OK, 'asp_solver_converged')
  call expect(converged == 1, 'asp_solver_converged says 1')
  call expect(counter%calls == cancel_after, 'a removed callback is not called')
  call expect_status(asp_solver_iterations(solver, iterations), ASP_OK, 'asp_solver_iterations')
  call expect(iterations >= cancel_after, 'the scene needs more iterations than the cancelled ' // &
              'solve ran, so that the cancellation meant something')
  call expect_status(asp_solver_evaluations(solver, count), ASP_OK, 'asp_solver_evaluations')
  call expect(count >= iterations, 'at least one evaluation per iteration of pk')
  call expect_status(asp_solver_transforms(solver, count), ASP_OK, 'asp_solver_transforms')
  call expect(count >= 2 * iterations, 'at least one FFT pair per iteration of pk')
  call expect_status(asp_solver_final_error(solver, error), ASP_OK, 'asp_solver_final_error')
  call expect(error <= tolerance, 'the final error meets the tolerance')
  call expect_status(asp_solver_elapsed_seconds(solver, value), ASP_OK, &
                     'asp_solver_elapsed_seconds')
  call expect(value >= 0 .and. ieee_is_finite(value), 'the elapsed seconds are finite')
  call expect_status(asp_solver_history_length(solver, rows), ASP_OK, &
                     'asp_solver_history_length')
  call expect(rows == iterations + 1, 'each solve starts a new history, one row per iteration')

  ! ---- scalar results and a field ----
  do k = ASP_CONTACT_FRACTION, ASP_ADHESION_RANGE
    call expect_status(asp_system_get(system, k, scalar), ASP_OK, 'asp_system_get')
    call expect(ieee_is_finite(scalar), 'every scalar result is finite')
  end do
  call expect_status(asp_system_get(system, ASP_MEAN_PRESSURE, scalar), ASP_OK, &
                     'asp_system_get(MEAN_PRESSURE)')
  call expect(abs(scalar - mean_pressure) <= 1d-12 * mean_pressure, &
              'the mean pressure is the one asked for')
  call expect_status(asp_system_get(system, ASP_TOTAL_FORCE, scalar), ASP_OK, &
                     'asp_system_get(TOTAL_FORCE)')
  call expect(abs(scalar - mean_pressure * box * box) <= 1d-12 * mean_pressure, &
              'the total force is the mean pressure times the area')
  call expect_status(asp_system_get(system, ASP_CONTACT_FRACTION, scalar), ASP_OK, &
                     'asp_system_get(CONTACT_FRACTION)')
  call expect(scalar > 0 .and. scalar < 0.5d0, 'a sphere touches in a small spot')
  call expect_status(asp_system_get(system, ASP_PENETRATION, scalar), ASP_OK, &
                     'asp_system_get(PENETRATION)')
  call expect(scalar > 0, 'the sphere is pressed in')
  call expect_status(asp_system_get(system, ASP_ELASTIC_ENERGY, scalar), ASP_OK, &
                     'asp_system_get(ELASTIC_ENERGY)')
  call expect(scalar > 0, 'the substrate stores elastic energy')
  call expect_status(asp_system_get(system, ASP_HISTORY_ERROR, scalar), &
                     ASP_ERR_INVALID_ARGUMENT, 'a history column as a scalar key')
  call expect_status(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, n * n), ASP_OK, &
                     'asp_system_get_field(PRESSURE)')
  call expect(minval(pressure) >= 0, 'a hard wall without adhesion pushes only')
  call expect(abs(sum(pressure) / (n * n) - mean_pressure) <= 1d-12 * mean_pressure, &
              'the pressure field has the mean pressure asked for')

  ! ---- history off: the next solve records nothing ----
  call expect_status(asp_solver_set_history(solver, 0_c_int), ASP_OK, &
                     'asp_solver_set_history(0)')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_OK, 'a warm solve without history')
  call expect_status(asp_solver_history_length(solver, rows), ASP_OK, &
                     'asp_solver_history_length')
  call expect(rows == 0, 'no history is recorded when it is off')

  ! ---- adhesion: bad arguments refused by name, then the sphere pulled by adhesion ----
  call expect_status(asp_system_set_adhesion(system, -1d-4, 1d-3), ASP_ERR_INVALID_ARGUMENT, &
                     'a negative work of adhesion')
  call expect(index(asp_last_error_text(), 'work_of_adhesion') > 0, &
              'the message names the work of adhesion: ' // asp_last_error_text())
  call expect_status(asp_system_set_adhesion(system, 1d-4, 0d0), ASP_ERR_INVALID_ARGUMENT, &
                     'a zero range')
  call expect(index(asp_last_error_text(), 'range') > 0, &
              'the message names the range: ' // asp_last_error_text())
  call expect_status(asp_system_get(system, ASP_PENETRATION, value), ASP_OK, &
                     'asp_system_get(PENETRATION)')
  call expect_status(asp_system_set_adhesion(system, 1d-4, 2d-3), ASP_OK, &
                     'asp_system_set_adhesion')
  call expect_status(asp_system_get(system, ASP_WORK_OF_ADHESION, scalar), ASP_OK, &
                     'asp_system_get(WORK_OF_ADHESION)')
  call expect(scalar == 1d-4, 'the work of adhesion is the one set')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, value), &
                     ASP_ERR_UNSUPPORTED, '"pk" refuses adhesion')
  call expect(index(asp_last_error_text(), 'adhesive hard wall') > 0, &
              'the message names the interaction: ' // asp_last_error_text())
  call expect_status(asp_solver_create('bugnicourt', adhesive_solver), ASP_OK, &
                     'asp_solver_create(bugnicourt)')
  call expect_status(asp_solver_set_option_string(adhesive_solver, 'variable', 'gap'), ASP_OK, &
                     'variable = gap')
  call expect_status(asp_solver_solve(adhesive_solver, system, ASP_CONTROL_PENETRATION, value), &
                     ASP_OK, 'bugnicourt on the gap with adhesion')
  call expect_status(asp_solver_converged(adhesive_solver, converged), ASP_OK, &
                     'asp_solver_converged')
  call expect(converged == 1, 'the adhesive solve converges')
  call expect_status(asp_system_get(system, ASP_ATTRACTIVE_FORCE, scalar), ASP_OK, &
                     'asp_system_get(ATTRACTIVE_FORCE)')
  call expect(scalar < 0, 'adhesion pulls')
  call expect_status(asp_system_get(system, ASP_INTERACTION_ENERGY, scalar), ASP_OK, &
                     'asp_system_get(INTERACTION_ENERGY)')
  call expect(scalar < 0, 'the interaction energy of adhesion is negative')
  ! ---- resolution: the cohesive zone (pi/4) E* rho^2/w over the pixel box/n, 2.01 pixels
  ! here; 1d-12 relative, the round-off of the library's logarithms (see tests/api) ----
  expected_ratio = atan(1d0) * modulus * 2d-3**2 / 1d-4 / (box / n)
  text = asp_system_check_resolution_text(system, value, flag, status)
  call expect_status(status, ASP_OK, 'asp_system_check_resolution_text')
  call expect(abs(value - expected_ratio) <= 1d-12 * expected_ratio .and. flag == 1, &
              'the adhesion is resolved, by its cohesive zone over the pixel')
  call expect(index(text, 'resolved: ') == 1, 'the sentence says resolved: ' // text)
  call expect_status(asp_system_set_adhesion(system, 1d-1, 2d-3), ASP_OK, &
                     'asp_system_set_adhesion, 1000 times stronger')
  call expect_status(asp_system_check_resolution(system, value, flag, sentence, &
                                                 len(sentence), length), ASP_OK, &
                     'asp_system_check_resolution')
  call expect(abs(value - expected_ratio / 1000) <= 1d-12 * expected_ratio / 1000 .and. &
              flag == 0, 'stronger adhesion is not resolved')
  call expect(index(sentence(1:length), 'lattice trapping') > 0, &
              'the sentence names lattice trapping: ' // sentence(1:length))
  call expect_status(asp_system_check_resolution(system, value, flag, small, &
                                                 int(len(small), c_int64_t), length), &
                     ASP_ERR_SIZE_MISMATCH, 'asp_system_check_resolution in 2 characters')
  call expect(length > len(small) .and. flag == 0, &
              'a buffer too small still gets the length and the flag')
  call expect_status(asp_system_set_adhesion(system, 0d0, 1d0), ASP_OK, &
                     'asp_system_set_adhesion(0): the plain hard wall again')
  text = asp_system_check_resolution_text(system, value, flag)
  call expect(value == 0 .and. flag == 1 .and. index(text, 'nothing') > 0, &
              'the plain hard wall has nothing to resolve: ' // text)
  call expect_status(asp_system_get(system, ASP_WORK_OF_ADHESION, scalar), ASP_OK, &
                     'asp_system_get(WORK_OF_ADHESION)')
  call expect(scalar == 0, 'no work of adhesion after setting 0')
  call asp_solver_destroy(adhesive_solver)
  ! ---- lbfgsb: its options set by name, then a solve under penetration
  ! control at pk's penetration, on the gap ----
  call expect_status(asp_solver_create('lbfgsb', lbfgsb), ASP_OK, 'asp_solver_create(lbfgsb)')
  call expect_status(asp_solver_set_option(lbfgsb, 'memory', 5d0), ASP_OK, &
                     'asp_solver_set_option(memory)')
  call expect_status(asp_solver_get_option(lbfgsb, 'memory', value), ASP_OK, &
                     'asp_solver_get_option(memory)')
  call expect(value == 5, 'the memory is the one set')
  call expect_status(asp_solver_set_option(lbfgsb, 'memory', 0d0), ASP_ERR_INVALID_ARGUMENT, &
                     'a memory of 0 is refused')
  call expect(index(asp_last_error_text(), 'memory') > 0, &
              'the message names the option: ' // asp_last_error_text())
  call expect_status(asp_solver_set_option_string(lbfgsb, 'variable', 'gap'), ASP_OK, &
                     'asp_solver_set_option_string(variable)')
  call expect(asp_solver_get_option_string_text(lbfgsb, 'variable') == 'gap', &
              'the variable is the one set')
  call expect_status(asp_solver_set_option(lbfgsb, 'tolerance', tolerance), ASP_OK, &
                     'asp_solver_set_option(tolerance) for lbfgsb')
  call expect_status(asp_solver_solve(lbfgsb, system, ASP_CONTROL_MEAN_GAP, mean_pressure), &
                     ASP_ERR_UNSUPPORTED, 'lbfgsb refuses mean-gap control')
  call expect_status(asp_system_get(system, ASP_PENETRATION, penetration), ASP_OK, &
                     'asp_system_get(PENETRATION) for lbfgsb')
  call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset before lbfgsb')
  call expect_status(asp_solver_solve(lbfgsb, system, ASP_CONTROL_PENETRATION, penetration), &
                     ASP_OK, 'lbfgsb under penetration control')
  call expect_status(asp_solver_converged(lbfgsb, converged), ASP_OK, &
                     'asp_solver_converged for lbfgsb')
  call expect(converged == 1, 'lbfgsb converges')
  call expect_status(asp_system_get(system, ASP_MEAN_PRESSURE, scalar), ASP_OK, &
                     'asp_system_get(MEAN_PRESSURE) after lbfgsb')
  ! The load of pk's solution, to what the tolerance 1e-10 leaves of the pressures.
  call expect(abs(scalar - mean_pressure) <= 1d-6 * mean_pressure, &
              'lbfgsb finds the load of the penetration')
  call asp_solver_destroy(lbfgsb)

  ! ---- soft potentials: the soft wall, the Lennard-Jones wall, a Fortran callback ----
  wall = soft_wall(1d-4, 2d-3, 5d-5, 2d-3)
  call expect_status(asp_system_set_soft_wall(system, wall%gamma_r, wall%rho_r, wall%gamma_a, &
                     wall%rho_a), ASP_OK, 'asp_system_set_soft_wall')
  call expect_status(asp_system_get(system, ASP_INTERACTION_ENERGY, scalar), ASP_OK, &
                     'asp_system_get(INTERACTION_ENERGY) of the soft wall')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_ERR_UNSUPPORTED, 'pk refuses a soft wall')
  call expect(index(asp_last_error_text(), 'soft wall') > 0, &
              'the message names the interaction: ' // asp_last_error_text())
  call expect_status(asp_system_set_soft_wall(system, wall%gamma_r, -1d0, wall%gamma_a, &
                     wall%rho_a), ASP_ERR_INVALID_ARGUMENT, 'asp_system_set_soft_wall, rho_r < 0')
  call expect(index(asp_last_error_text(), "'rho_r'") > 0, &
              'the message names rho_r: ' // asp_last_error_text())

  call expect_status(asp_system_set_lennard_jones(system, 1d-4, 2d-3), ASP_OK, &
                     'asp_system_set_lennard_jones')
  call expect_status(asp_system_set_lennard_jones(system, 1d-4, 0d0), ASP_ERR_INVALID_ARGUMENT, &
                     'asp_system_set_lennard_jones, z0 = 0')
  call expect(index(asp_last_error_text(), "'equilibrium_distance'") > 0, &
              'the message names equilibrium_distance: ' // asp_last_error_text())
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_ERR_UNSUPPORTED, 'pk refuses a Lennard-Jones wall')

  call expect_status(asp_system_set_potential(system, c_funloc(soft_wall_potential), &
                     c_loc(wall), 0_c_int), ASP_OK, 'asp_system_set_potential')
  call expect_status(asp_system_get(system, ASP_INTERACTION_ENERGY, value), ASP_OK, &
                     'asp_system_get(INTERACTION_ENERGY) of the Fortran potential')
  call expect(wall%calls == 1, 'the potential is called once for all pixels')
  ! The same sum of the same terms as the built-in wall's, to rounding.
  call expect(abs(value - scalar) <= 1d-13 * abs(scalar) .and. scalar /= 0, &
              'the Fortran soft wall has the built-in one''s energy')
  ! Solved with the Fortran potential and with the built-in wall, by the preconditioned
  ! L-BFGS under the same load: the same mean gap, to what the tolerance leaves.
  call expect_status(asp_solver_create('lbfgs_fourier' // c_null_char, soft_solver), ASP_OK, &
                     'asp_solver_create(lbfgs_fourier)')
  call expect_status(asp_solver_set_tolerance(soft_solver, tolerance), ASP_OK, &
                     'asp_solver_set_tolerance(lbfgs_fourier)')
  call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset')
  call expect_status(asp_solver_solve(soft_solver, system, ASP_CONTROL_MEAN_PRESSURE, &
                     mean_pressure), ASP_OK, 'lbfgs_fourier with the Fortran potential')
  call expect_status(asp_solver_converged(soft_solver, converged), ASP_OK, &
                     'asp_solver_converged(lbfgs_fourier)')
  call expect(converged == 1, 'lbfgs_fourier converges with the Fortran potential')
  call expect_status(asp_system_get(system, ASP_MEAN_GAP, value), ASP_OK, &
                     'asp_system_get(MEAN_GAP) with the Fortran potential')
  call expect_status(asp_system_set_soft_wall(system, wall%gamma_r, wall%rho_r, wall%gamma_a, &
                     wall%rho_a), ASP_OK, 'asp_system_set_soft_wall again')
  call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset')
  call expect_status(asp_solver_solve(soft_solver, system, ASP_CONTROL_MEAN_PRESSURE, &
                     mean_pressure), ASP_OK, 'lbfgs_fourier with the built-in soft wall')
  call expect_status(asp_system_get(system, ASP_MEAN_GAP, scalar), ASP_OK, &
                     'asp_system_get(MEAN_GAP) with the built-in soft wall')
  call expect(abs(value - scalar) <= 1d-8 * abs(scalar) .and. scalar > 0, &
              'the Fortran potential gives the built-in wall''s solution')
  call asp_solver_destroy(soft_solver)
  ! Every unconstrained solver, by name, reaches the same mean gap on the built-in wall.
  do k = 1, size(unconstrained)
    call expect_status(asp_solver_create(trim(unconstrained(k)), soft_solver), ASP_OK, &
                       'asp_solver_create(' // trim(unconstrained(k)) // ')')
    call expect_status(asp_solver_set_tolerance(soft_solver, tolerance), ASP_OK, &
                       'asp_solver_set_tolerance(' // trim(unconstrained(k)) // ')')
    call expect_status(asp_solver_set_max_iterations(soft_solver, 200000_c_int64_t), ASP_OK, &
                       'asp_solver_set_max_iterations(' // trim(unconstrained(k)) // ')')
    call expect_status(asp_system_reset(system), ASP_OK, 'asp_system_reset')
    call expect_status(asp_solver_solve(soft_solver, system, ASP_CONTROL_MEAN_PRESSURE, &
                       mean_pressure), ASP_OK, trim(unconstrained(k)) // ' on the soft wall')
    call expect_status(asp_solver_converged(soft_solver, converged), ASP_OK, &
                       'asp_solver_converged(' // trim(unconstrained(k)) // ')')
    call expect(converged == 1, trim(unconstrained(k)) // ' converges on the soft wall')
    call expect_status(asp_system_get(system, ASP_MEAN_GAP, value), ASP_OK, &
                       'asp_system_get(MEAN_GAP) after ' // trim(unconstrained(k)))
    call expect(abs(value - scalar) <= 1d-7 * abs(scalar), &
                trim(unconstrained(k)) // ' finds the mean gap of lbfgs_fourier')
    call asp_solver_destroy(soft_solver)
  end do
  call expect_status(asp_system_set_potential(system, c_funloc(soft_wall_potential), &
                     c_loc(wall), 0_c_int), ASP_OK, 'asp_system_set_potential again')

  call expect_status(asp_system_set_potential(system, c_null_funptr, c_null_ptr, 0_c_int), &
                     ASP_ERR_NULL_POINTER, 'asp_system_set_potential without a function')
  call expect(index(asp_last_error_text(), "'fn'") > 0, &
              'the message names fn: ' // asp_last_error_text())
  call expect_status(asp_system_set_potential(system, c_funloc(soft_wall_potential), &
                     c_loc(wall), 1_c_int), ASP_OK, 'asp_system_set_potential with the hard wall')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_ERR_UNSUPPORTED, 'pk refuses a user potential')

  call expect_status(asp_system_set_hard_wall(system), ASP_OK, 'asp_system_set_hard_wall')
  call expect_status(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure), &
                     ASP_OK, 'pk on the hard wall again')
  call expect_status(asp_solver_converged(solver, converged), ASP_OK, 'asp_solver_converged')
  call expect(converged == 1, 'pk converges on the hard wall again')

  ! ---- the generic interfaces: strings without c_null_char, default integers, arrays of rank
  ! 1 and 2 ----
  ! The call that used to compile and then read past the string.
  call expect_status(asp_solver_create('pk', plain_solver), ASP_OK, "asp_solver_create('pk')")
  call expect(index(asp_solver_describe_text(plain_solver), 'pk') == 1, &
              'the solver made from a plain string is pk')
  call asp_solver_destroy(plain_solver)
  call expect_status(asp_solver_create('pk' // c_null_char, plain_solver), ASP_OK, &
                     'asp_solver_create with the NUL already there')
  call expect_status(asp_solver_set_max_iterations(plain_solver, 100), ASP_OK, &
                     'asp_solver_set_max_iterations with a default integer')
  call expect_status(asp_solver_get_option(plain_solver, 'max_iterations', value), ASP_OK, &
                     'asp_solver_get_option(max_iterations)')
  call expect(value == 100, 'max_iterations set from a default integer reads back')
  call expect_status(asp_solver_set_option(plain_solver, 'stall_window', 200), ASP_OK, &
                     'asp_solver_set_option with a default-integer value')
  call expect_status(asp_solver_set_option(plain_solver, 'stall_window', 300_c_int64_t), &
                     ASP_OK, 'asp_solver_set_option with an integer(c_int64_t) value')
  call expect_status(asp_solver_get_option(plain_solver, 'stall_window' // c_null_char, value), &
                     ASP_OK, 'asp_solver_get_option with the NUL already there')
  call expect(value == 300, 'stall_window set from an integer reads back')
  call expect_status(asp_solver_set_option(plain_solver, 'stall_window', 2.5d0), &
                     ASP_ERR_INVALID_ARGUMENT, 'a fractional stall_window')
  call asp_solver_destroy(plain_solver)
  call expect_status(asp_solver_create('bugnicourt', plain_solver), ASP_OK, &
                     "asp_solver_create('bugnicourt')")
  call expect_status(asp_solver_set_option_string(plain_solver, 'variable', 'gap   '), ASP_OK, &
                     'asp_solver_set_option_string with a blank-padded value')
  option_text = ''
  status = asp_solver_get_option_string(plain_solver, 'variable', option_text, &
                                        len(option_text), length)
  call expect_status(status, ASP_OK, 'asp_solver_get_option_string with a default-integer size')
  call expect(length == 3 .and. option_text(1:3) == 'gap' .and. option_text(4:4) == c_null_char, &
              'asp_solver_get_option_string writes the value and its NUL')
  status = asp_solver_describe(plain_solver, option_text, 4, length)
  call expect_status(status, ASP_ERR_SIZE_MISMATCH, 'asp_solver_describe into 4 characters')
  call expect(option_text(1:4) == 'bug' // c_null_char, 'the description is cut to 3 characters')
  status = asp_algorithms(large, len(large), length)
  call expect_status(status, ASP_OK, 'asp_algorithms with a default-integer size')
  call expect(large(1:length) == names, 'asp_algorithms gives the names')
  call asp_solver_destroy(plain_solver)

  call expect_status(asp_grid_create_2d(m, m, box, box, small_grid), ASP_OK, &
                     'asp_grid_create_2d with default integers')
  call expect_status(asp_grid_get_shape(small_grid, dimension, nx, ny, pixels), ASP_OK, &
                     'asp_grid_get_shape of the small grid')
  call expect(nx == m .and. ny == m .and. pixels == m * m, 'the small grid has its shape')
  call expect_status(asp_topography_sinusoid(small_grid, 1d-2, 2, 1, field, size(field)), &
                     ASP_OK, 'asp_topography_sinusoid with default integers, rank 2')
  call expect_status(asp_topography_sinusoid(small_grid, 1d-2, 2_c_int64_t, 1_c_int64_t, &
                     line_field, int(m * m, c_int64_t)), ASP_OK, &
                     'asp_topography_sinusoid with integer(c_int64_t), rank 1')
  call expect(all(reshape(field, [m * m]) == line_field), &
              'a rank-2 and a rank-1 array receive the same heights')
  call expect_status(asp_topography_self_affine(small_grid, 0.8d0, box, box / 4, box / 8, &
                     ASP_RMS_HEIGHT, 1d-2, 7, field, size(field)), ASP_OK, &
                     'asp_topography_self_affine with a default-integer seed')
  call expect_status(asp_topography_self_affine(small_grid, 0.8d0, box, box / 4, box / 8, &
                     ASP_RMS_HEIGHT, 1d-2, 7_c_int64_t, line_field, int(m * m, c_int64_t)), &
                     ASP_OK, 'asp_topography_self_affine with an integer(c_int64_t) seed')
  call expect(all(reshape(field, [m * m]) == line_field), &
              'the same seed gives the same surface through either generic variant')
  call expect_status(asp_topography_statistics(small_grid, field, size(field), rms_height, &
                     rms_slope, rms_curvature), ASP_OK, 'asp_topography_statistics, rank 2')
  call expect(abs(rms_height - 1d-2) <= 1d-12, 'the rms height is the one asked for')
  call expect_status(asp_topography_power_spectrum(small_grid, field, size(field), size(q), q, &
                     c), ASP_OK, 'asp_topography_power_spectrum with default integers')
  call expect(all(c >= 0) .and. any(c > 0), 'the spectrum has power')
  call expect_status(asp_topography_detrend(small_grid, ASP_DETREND_MEAN, field, size(field)), &
                     ASP_OK, 'asp_topography_detrend, rank 2')
  call expect_status(asp_topography_paraboloid(small_grid, radius, field, size(field)), &
                     ASP_OK, 'asp_topography_paraboloid, rank 2')
  call expect_status(asp_topography_flat(small_grid, line_field, size(line_field)), ASP_OK, &
                     'asp_topography_flat, rank 1')
  call expect(all(line_field == 0), 'the flat surface is flat')
  call expect_status(asp_system_create(small_grid, modulus, small_system), ASP_OK, &
                     'asp_system_create on the small grid')
  call expect_status(asp_system_set_topography(small_system, field, size(field)), ASP_OK, &
                     'asp_system_set_topography, rank 2, default integer')
  call expect_status(asp_system_set_topography(small_system, field, size(field) - 1), &
                     ASP_ERR_SIZE_MISMATCH, 'a wrong default-integer count is refused')
  call expect_status(asp_system_get_field(small_system, ASP_FIELD_TOPOGRAPHY, line_field, &
                     size(line_field)), ASP_OK, 'asp_system_get_field, rank 1, default integer')
  call expect(all(reshape(field, [m * m]) == line_field), &
              'the topography comes back as it went in')
  call asp_system_destroy(small_system)
  call asp_grid_destroy(small_grid)

  ! ---- FFTW wisdom ----
  call expect_status(asp_fft_export_wisdom(wisdom_file), ASP_OK, 'asp_fft_export_wisdom')
  call expect_status(asp_fft_import_wisdom(wisdom_file), ASP_OK, 'asp_fft_import_wisdom')
  call expect_status(asp_fft_import_wisdom('no/such/directory/x.wisdom' // c_null_char), &
                     ASP_ERR_IO, 'asp_fft_import_wisdom of a missing file')
  call expect(index(asp_last_error_text(), 'no/such/directory/x.wisdom') > 0, &
              'the message names the path: ' // asp_last_error_text())
  open (newunit=unit, file=wisdom_file, status='old', iostat=status)
  if (status == 0) close (unit, status='delete')

  ! ---- a free half-space: the same sphere without periodic images ----
  call expect_status(asp_system_create_free(grid, modulus, free_system), ASP_OK, &
                     'asp_system_create_free')
  call expect_status(asp_system_set_topography(free_system, heights, n * n), ASP_OK, &
                     'asp_system_set_topography on a free system')
  call expect_status(asp_solver_solve(solver, free_system, ASP_CONTROL_MEAN_PRESSURE, &
                     mean_pressure), ASP_OK, 'pk on a free system')
  call expect_status(asp_solver_converged(solver, converged), ASP_OK, 'asp_solver_converged')
  call expect(converged == 1, 'pk converges on a free system')
  ! The stiffness of that state: the sphere's force grows faster than linearly with the
  ! penetration (as delta^(3/2)), so dF/d(delta) exceeds F/delta. Refused for another system.
  call expect_status(asp_solver_normal_stiffness(solver, free_system, stiffness), ASP_OK, &
                     'asp_solver_normal_stiffness of a free system')
  call expect_status(asp_system_get(free_system, ASP_TOTAL_FORCE, scalar), ASP_OK, &
                     'asp_system_get(TOTAL_FORCE) of a free system')
  call expect_status(asp_system_get(free_system, ASP_PENETRATION, value), ASP_OK, &
                     'asp_system_get(PENETRATION) of a free system')
  call expect(stiffness * box * box > scalar / value, 'dF/d(delta) exceeds F/delta')
  call expect_status(asp_solver_normal_stiffness(solver, system, stiffness), &
                     ASP_ERR_INVALID_STATE, 'asp_solver_normal_stiffness of another system')
  call expect(index(asp_last_error_text(), 'not the state') > 0, &
              'the message says why: ' // asp_last_error_text())
  call expect_status(asp_system_get(free_system, ASP_ELASTIC_ENERGY, scalar), ASP_OK, &
                     'asp_system_get(ELASTIC_ENERGY) of a free system')
  call expect(scalar > 0, 'a free substrate stores elastic energy')
  call expect_status(asp_system_get(free_system, ASP_MEAN_MODE_ENERGY, scalar), ASP_OK, &
                     'asp_system_get(MEAN_MODE_ENERGY) of a free system')
  call expect(scalar == 0, 'a free system has no mean-mode energy')
  call expect_status(asp_system_set_k0(free_system, 1d0), ASP_ERR_UNSUPPORTED, &
                     'asp_system_set_k0 on a free system')
  call expect(index(asp_last_error_text(), 'free half-space') > 0, &
              'the message says why: ' // asp_last_error_text())
  call expect_status(asp_grid_create_1d(n, box, line), ASP_OK, 'asp_grid_create_1d')
  call expect_status(asp_system_create_free(line, modulus, no_system), ASP_ERR_UNSUPPORTED, &
                     'asp_system_create_free on a 1D grid')
  call expect(.not. c_associated(no_system), 'a refused system is NULL')
  call expect(index(asp_last_error_text(), "'grid'") > 0, &
              'the message names the grid: ' // asp_last_error_text())
  call asp_grid_destroy(line)
  call asp_system_destroy(free_system)

  ! ---- an elastic layer on a rigid base: its own K~(0) = M/t, which cannot be set ----
  ! E* = 1, nu = 0.3, t = 0.1: M = E* (1 - nu^2)(1 - nu)/((1 + nu)(1 - 2 nu)) = 1.225.
  call expect_status(asp_system_create_layer(grid, modulus, 0.3d0, 0.1d0, layer_system), &
                     ASP_OK, 'asp_system_create_layer')
  call expect_status(asp_system_get(layer_system, ASP_K0, scalar), ASP_OK, &
                     'asp_system_get(K0) of a layer')
  call expect(abs(scalar - 12.25d0) < 1d-12 * 12.25d0, 'the layer''s K~(0) is M/t')
  call expect_status(asp_system_set_k0(layer_system, 1d0), ASP_ERR_UNSUPPORTED, &
                     'asp_system_set_k0 on a layer')
  call expect(index(asp_last_error_text(), 'elastic layer') > 0, &
              'the message says why: ' // asp_last_error_text())
  call expect_status(asp_system_set_topography(layer_system, heights, n * n), ASP_OK, &
                     'asp_system_set_topography on a layer')
  call expect_status(asp_solver_solve(solver, layer_system, ASP_CONTROL_MEAN_PRESSURE, &
                     mean_pressure), ASP_OK, 'pk on a layer')
  call expect_status(asp_solver_converged(solver, converged), ASP_OK, 'asp_solver_converged')
  call expect(converged == 1, 'pk converges on a layer')
  call expect_status(asp_system_get(layer_system, ASP_MEAN_PRESSURE, scalar), ASP_OK, &
                     'asp_system_get(MEAN_PRESSURE) of a layer')
  call expect(abs(scalar - mean_pressure) < 1d-9 * mean_pressure, 'the layer carries the load')
  call asp_system_destroy(layer_system)
  call expect_status(asp_system_create_layer(grid, modulus, 0.5d0, 0.1d0, layer_system), &
                     ASP_ERR_INVALID_ARGUMENT, 'asp_system_create_layer with nu = 0.5')
  call expect(.not. c_associated(layer_system), 'a refused layer is NULL')
  call expect(index(asp_last_error_text(), "'poisson_ratio'") > 0, &
              'the message names the argument: ' // asp_last_error_text())

  call asp_solver_destroy(solver)
  call asp_system_destroy(system)
  call asp_grid_destroy(grid)
  deallocate (heights, pressure, text, names)

  if (failures > 0) then
    print '(i0, a)', failures, ' checks failed'
    error stop 1
  end if
  print '(a)', 'all checks passed'
end program test_api
