! SPDX-License-Identifier: GPL-2.0-or-later
! The rough contact of rough_contact.f90 on a grid shared among MPI processes: each process
! holds a slab of whole rows (asp_grid_get_slab), generates its rows of the self-affine surface
! and passes and receives arrays of those rows only; every call is collective. Process 0 prints
! the results, which are the whole grid's. Every process also solves the same scene on a grid
! of its own, not distributed, and the two must agree to 1e-10 (the example stops with an error
! otherwise): the answer does not depend on the number of processes.
!
!   mpirun -np 2 ./example_distributed_contact_fortran
program distributed_contact
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_null_ptr
  use mpi
  use asperity
  implicit none

  integer, parameter :: n = 128
  real(c_double), parameter :: length = 1.0d0, modulus = 1.0d0, rms_slope = 0.1d0
  real(c_double), parameter :: mean_pressure = 0.002d0, tolerance = 1d-11
  type(c_ptr) :: grid = c_null_ptr, serial_grid = c_null_ptr
  real(c_double), allocatable :: heights(:, :), pressure(:, :)
  real(c_double), allocatable :: serial_heights(:, :), serial_pressure(:, :)
  real(c_double) :: fraction, gap, serial_fraction, serial_gap, largest
  integer(c_int64_t) :: local_ny, row_offset, local_pixels, iterations
  integer :: rank, processes, ierr

  call MPI_Init(ierr)
  call MPI_Comm_rank(MPI_COMM_WORLD, rank, ierr)
  call MPI_Comm_size(MPI_COMM_WORLD, processes, ierr)

  ! The distributed grid: this process's rows are rows row_offset+1 .. row_offset+local_ny of
  ! the whole grid (Fortran's count from 1), x fastest as everywhere in asperity.
  call check(asp_grid_create_mpi(MPI_COMM_WORLD, n, n, length, length, grid))
  call check(asp_grid_get_slab(grid, local_ny, row_offset, local_pixels))
  allocate (heights(n, local_ny), pressure(n, local_ny))
  ! Each process generates only its rows: the generator gives the same global surface for any
  ! number of processes.
  call check(asp_topography_self_affine(grid, 0.8d0, length, length / 4, 4 * length / n, &
                                        ASP_RMS_SLOPE, rms_slope, 42, heights, size(heights)))
  call solve(grid, heights, pressure, fraction, gap, iterations)

  ! The same scene on a grid of this process alone.
  call check(asp_grid_create_2d(n, n, length, length, serial_grid))
  allocate (serial_heights(n, n), serial_pressure(n, n))
  call check(asp_topography_self_affine(serial_grid, 0.8d0, length, length / 4, &
                                        4 * length / n, ASP_RMS_SLOPE, rms_slope, 42, &
                                        serial_heights, size(serial_heights)))
  call solve(serial_grid, serial_heights, serial_pressure, serial_fraction, serial_gap)

  if (rank == 0) then
    print '(a, i0, a, i0, a, i0, a)', 'grid ', n, ' x ', n, ' on ', processes, ' processes'
    print '(a, f10.7, a, es12.5, a, i0, a)', 'contact fraction ', fraction, ', mean gap ', gap, &
        ' (', iterations, ' iterations)'
    print '(a, f10.7, a, es12.5)', 'one process:     ', serial_fraction, ', mean gap ', serial_gap
  end if

  ! The distributed results against the serial ones, on every process: its own rows of the
  ! surface exactly (the generator's promise), the pressure to 1e-10 of its largest value,
  ! the scalars to 1e-10 relative.
  if (any(heights /= serial_heights(:, row_offset + 1:row_offset + local_ny))) &
      error stop 'the surface is not the serial one'
  largest = maxval(abs(serial_pressure))
  if (any(abs(pressure - serial_pressure(:, row_offset + 1:row_offset + local_ny)) &
          > 1d-10 * largest)) error stop 'the pressure is not the serial one'
  if (abs(fraction - serial_fraction) > 1d-10 * serial_fraction) &
    error stop 'the contact fraction is not the serial one'
  if (abs(gap - serial_gap) > 1d-10 * abs(serial_gap)) error stop 'the mean gap is not the serial one'

  call asp_grid_destroy(serial_grid)
  call asp_grid_destroy(grid)          ! before MPI_Finalize
  call MPI_Finalize(ierr)

contains

  ! A hard wall pressed to the mean pressure with Polonsky & Keer's method; on a distributed
  ! grid heights and pressure are this process's rows.
  subroutine solve(on, h, p, contact_fraction, mean_gap, iterations)
    type(c_ptr), intent(in) :: on
    real(c_double), intent(in) :: h(:, :)
    real(c_double), intent(out) :: p(:, :), contact_fraction, mean_gap
    integer(c_int64_t), intent(out), optional :: iterations
    type(c_ptr) :: system, solver
    integer(c_int) :: converged
    system = c_null_ptr
    solver = c_null_ptr
    call check(asp_system_create(on, modulus, system))
    call check(asp_system_set_topography(system, h, size(h)))
    call check(asp_solver_create('pk', solver))
    call check(asp_solver_set_tolerance(solver, tolerance))
    call check(asp_solver_set_max_iterations(solver, 1000))
    call check(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure))
    call check(asp_solver_converged(solver, converged))
    if (converged /= 1) error stop 'the solve did not converge'
    if (present(iterations)) call check(asp_solver_iterations(solver, iterations))
    call check(asp_system_get(system, ASP_CONTACT_FRACTION, contact_fraction))
    call check(asp_system_get(system, ASP_MEAN_GAP, mean_gap))
    call check(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, size(p)))
    call asp_solver_destroy(solver)
    call asp_system_destroy(system)
  end subroutine

  ! A failed call fails on every process of a distributed grid, with the same message, so
  ! every process stops here; MPI_Abort makes sure that none is left waiting.
  subroutine check(status)
    integer(c_int), intent(in) :: status
    integer :: ierror
    if (status /= ASP_OK) then
      print '(a, i0, a, a)', 'process ', rank, ': asperity error: ', asp_last_error_text()
      call MPI_Abort(MPI_COMM_WORLD, 1, ierror)
    end if
  end subroutine

end program distributed_contact
