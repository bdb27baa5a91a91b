! SPDX-License-Identifier: GPL-2.0-or-later
! Fortran 2003 interface to asperity, through ISO_C_BINDING.
!
! Every constant and every function of include/asperity/asperity.h has a public counterpart of
! the same name here (the test fortran.mirrors_header checks it): constants are integer(c_int)
! parameters; each function is either its bind(c) interface itself or a generic interface of
! that name which holds the bind(c) interface together with the module's own variants. So
! does every function of include/asperity/asperity_mpi.h but asp_grid_create_mpi, whose C
! MPI_Comm Fortran cannot pass: the module's asp_grid_create_mpi takes MPI's Fortran handle.
!
! Distributed grids (a libasperity built with MPI): after MPI_Init, every process calls
!
!   status = asp_grid_create_mpi(MPI_COMM_WORLD, nx, ny, lx, ly, grid)  ! comm%MPI_VAL (mpi_f08)
!   status = asp_grid_get_slab(grid, local_ny, row_offset, local_pixels)
!
! and then makes the same calls as the others, in the same order (they are collective). Each
! process holds local_ny whole rows from row_offset on (0-based): its arrays are h(nx, local_ny)
! with counts of local_pixels; scalar results are the whole grid's, the same on every process.
!
! Kinds. Handles are type(c_ptr); reals are real(c_double) only (a default real, single
! precision on every common compiler, is refused at compile time rather than widened
! silently); flags, keys and statuses are integer(c_int); callbacks are type(c_funptr) (pass a
! bind(c) procedure with c_funloc) and their user data type(c_ptr) (c_loc of a variable with
! the target attribute, or c_null_ptr). Integer inputs that are counts, sizes, seeds or
! periods are integer(c_int64_t) in C; the generic interfaces take them as default integers
! (integer(c_int)) as well, all the integer inputs of one call of one kind:
!
!   status = asp_grid_create_2d(256, 256, 1d0, 1d0, grid)
!   status = asp_topography_self_affine(grid, 0.8d0, 1d0, 0.25d0, 1d0/64, ASP_RMS_SLOPE, &
!                                       0.1d0, 42, h, size(h))
!   status = asp_solver_set_max_iterations(solver, 100)
! Integer outputs (asp_grid_get_shape, asp_solver_iterations, ..., the length of a text) stay
! integer(c_int64_t), which no count overflows.
!
! Arrays are ordinary Fortran arrays, of rank 1 or 2: a field h(nx, ny) is exactly the C
! layout (x fastest) and goes to C without a copy when it is contiguous (a non-contiguous
! section is copied in and out by the compiler).
!
! The generic interfaces of the functions that take a field, and their variants (rank 1 or 2,
! default or c_int64_t counts), are written by tools/generate_fortran_arrays.py from one
! template, between the lines that say so: change its table and run it rather than edit
! them (the test fortran.module_up_to_date compares).
!
! Strings going in are plain Fortran strings: trailing blanks are dropped and the NUL is
! added by the module, so asp_solver_create('pk', solver) works, and so does a blank-padded
! character variable. A string that already holds a c_null_char is cut after it and passed
! on as it is ('pk'//c_null_char still works). Text coming back is either a C pointer, which
! asp_string() turns into a Fortran string, or is written into a character variable with
! its size, the length of the whole text coming back in length (integer(c_int64_t)), as the
! header's asp_algorithms describes:
!
!   character(len=64) :: names
!   integer(c_int64_t) :: length
!   status = asp_algorithms(names, len(names), length)   ! names(1:length)
!
! Helpers that spare the buffer, not part of the C interface: names ending in _text return
! the text as an allocatable character, and take an optional status argument when the C
! call can fail ('' is returned then): asp_status_text(status), asp_last_error_text(),
! asp_version_text(), asp_algorithms_text([status]), asp_solver_describe_text(solver
! [, status]), asp_solver_get_option_string_text(solver, name [, status]),
! asp_system_check_resolution_text(system [, ratio, resolved, status]).
!
! The progress callback's signature is the abstract interface asp_progress_fn:
!
!   function on_progress(iteration, seconds, error, user_data) result(stop) bind(c)
!     integer(c_int64_t), value :: iteration
!     real(c_double), value :: seconds, error
!     type(c_ptr), value :: user_data
!     integer(c_int) :: stop                  ! 0 to go on, anything else cancels
!   end function
!   status = asp_solver_set_progress(solver, c_funloc(on_progress), c_loc(counter))
!
! A potential is the abstract interface asp_potential_fn: it writes phi, phi' and phi'' at n
! gaps (physical units); d2phi is a C pointer, NULL when the solver does not need phi'':
!
!   function my_potential(n, gap, phi, dphi, d2phi, user_data) result(status) bind(c)
!     integer(c_int64_t), value :: n
!     real(c_double), intent(in) :: gap(n)
!     real(c_double), intent(out) :: phi(n), dphi(n)
!     type(c_ptr), value :: d2phi, user_data
!     integer(c_int) :: status                ! 0 to go on, anything else ends the solve
!     real(c_double), pointer :: curvature(:)
!     ...
!     if (c_associated(d2phi)) then
!       call c_f_pointer(d2phi, curvature, [n])
!       ...
!     end if
!   end function
!   status = asp_system_set_potential(system, c_funloc(my_potential), c_null_ptr, 0)
module asperity
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_funptr, c_char, &
                                         c_null_char, c_associated, c_f_pointer
  implicit none
  private

  ! Status codes
  integer(c_int), parameter, public :: ASP_OK = 0, ASP_ERR_NULL_POINTER = 1, &
      ASP_ERR_INVALID_ARGUMENT = 2, ASP_ERR_SIZE_MISMATCH = 3, ASP_ERR_OUT_OF_MEMORY = 4, &
      ASP_ERR_UNSUPPORTED = 5, ASP_ERR_INVALID_STATE = 6, ASP_ERR_FFT = 7, &
      ASP_ERR_CALLBACK = 8, ASP_ERR_INTERNAL = 9, ASP_ERR_IO = 10
  ! FFT planning
  integer(c_int), parameter, public :: ASP_FFT_ESTIMATE = 101, ASP_FFT_MEASURE = 102, &
                                        ASP_FFT_PATIENT = 103
  ! Self-affine normalisation
  integer(c_int), parameter, public :: ASP_RMS_HEIGHT = 201, ASP_RMS_SLOPE = 202
  ! Scalar results
  integer(c_int), parameter, public :: ASP_CONTACT_FRACTION = 301, ASP_MEAN_PRESSURE = 302, &
      ASP_MEAN_GAP = 303, ASP_ELASTIC_ENERGY = 304, ASP_PENETRATION = 305, ASP_TOTAL_FORCE = 306, &
      ASP_K0 = 307, ASP_REFERENCE_PRESSURE = 308, ASP_MEAN_MODE_ENERGY = 309, &
      ASP_ATTRACTIVE_FRACTION = 310, ASP_REPULSIVE_FORCE = 311, ASP_ATTRACTIVE_FORCE = 312, &
      ASP_INTERACTION_ENERGY = 313, ASP_WORK_OF_ADHESION = 314, ASP_ADHESION_RANGE = 315, &
      ASP_COMPRESSIVE_FRACTION = 316
  ! Fields
  integer(c_int), parameter, public :: ASP_FIELD_PRESSURE = 401, ASP_FIELD_GAP = 402, &
      ASP_FIELD_DISPLACEMENT = 403, ASP_FIELD_TOPOGRAPHY = 404, ASP_FIELD_CONTACT = 405
  ! Controls
  integer(c_int), parameter, public :: ASP_CONTROL_MEAN_PRESSURE = 501, &
      ASP_CONTROL_PENETRATION = 502, ASP_CONTROL_MEAN_GAP = 503
  ! History columns
  integer(c_int), parameter, public :: ASP_HISTORY_ITERATION = 601, &
      ASP_HISTORY_EVALUATIONS = 602, ASP_HISTORY_TRANSFORMS = 603, ASP_HISTORY_SECONDS = 604, &
      ASP_HISTORY_ERROR = 605, ASP_HISTORY_OBJECTIVE = 606, ASP_HISTORY_CONTACT_FRACTION = 607
  ! Termination reasons
  integer(c_int), parameter, public :: ASP_TERMINATION_CONVERGED = 701, &
      ASP_TERMINATION_ITERATION_LIMIT = 702, ASP_TERMINATION_CANCELLED = 703, &
      ASP_TERMINATION_STALLED = 704, ASP_TERMINATION_BREAKDOWN = 705, &
      ASP_TERMINATION_SEPARATED = 706
  ! Detrending modes
  integer(c_int), parameter, public :: ASP_DETREND_MEAN = 801, ASP_DETREND_PLANE = 802, &
      ASP_DETREND_CURVATURE = 803
  ! Solver report keys (asp_solver_get)
  integer(c_int), parameter, public :: ASP_REPORT_TERMINATION = 901, &
      ASP_REPORT_CONVERGED = 902, ASP_REPORT_ITERATIONS = 903, ASP_REPORT_EVALUATIONS = 904, &
      ASP_REPORT_TRANSFORMS = 905, ASP_REPORT_FINAL_ERROR = 906, &
      ASP_REPORT_ELAPSED_SECONDS = 907, ASP_REPORT_HISTORY_LENGTH = 908

  public :: asp_status_string, asp_last_error_message, asp_version_string, asp_abi_version
  public :: asp_grid_create_1d, asp_grid_create_2d, asp_grid_destroy, asp_grid_get_shape, &
            asp_grid_get_box, asp_grid_set_fft_planning, asp_grid_set_threads, &
            asp_grid_get_threads, asp_grid_get_slab, asp_fft_export_wisdom, &
            asp_fft_import_wisdom
  public :: asp_grid_create_mpi, asp_grid_create_mpi_f
  public :: asp_topography_flat, asp_topography_sphere, asp_topography_paraboloid, &
            asp_topography_sinusoid, asp_topography_double_sinewave, &
            asp_topography_self_affine, asp_topography_statistics, asp_topography_detrend, &
            asp_topography_power_spectrum
  public :: asp_system_create, asp_system_create_free, asp_system_create_layer, &
            asp_system_destroy, &
            asp_system_set_topography, &
            asp_system_set_k0, asp_system_set_adhesion, asp_system_set_soft_wall, &
            asp_system_set_lennard_jones, asp_system_set_hard_wall, asp_system_set_potential, &
            asp_system_set_reference_pressure, asp_system_reset, &
            asp_system_get, asp_system_get_field, asp_system_check_resolution
  public :: asp_algorithms
  public :: asp_solver_create, asp_solver_destroy, asp_solver_describe, asp_solver_set_option, &
            asp_solver_set_option_string, asp_solver_get_option, asp_solver_get_option_string, &
            asp_solver_set_tolerance, asp_solver_set_max_iterations, asp_solver_set_progress, &
            asp_solver_set_history, asp_solver_solve, asp_solver_supports, asp_solver_get, &
            asp_solver_termination, &
            asp_solver_iterations, asp_solver_evaluations, asp_solver_transforms, &
            asp_solver_final_error, asp_solver_converged, &
            asp_solver_elapsed_seconds, asp_solver_history_length, asp_solver_get_history, &
            asp_solver_normal_stiffness
  public :: asp_progress_fn, asp_potential_fn
  ! Helpers (see the top of this file)
  public :: asp_string
  public :: asp_status_text, asp_last_error_text, asp_version_text, asp_algorithms_text, &
            asp_solver_describe_text, asp_solver_get_option_string_text, &
            asp_system_check_resolution_text

  ! The progress callback: called once per iteration with the iteration number (0 is the
  ! starting point), the seconds since the solve started and the error; return 0 to go on,
  ! anything else to cancel the solve cleanly (ASP_TERMINATION_CANCELLED).
  abstract interface
    function asp_progress_fn(iteration, seconds, error, user_data) bind(c)
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: iteration
      real(c_double), value :: seconds, error
      type(c_ptr), value :: user_data
      integer(c_int) :: asp_progress_fn
    end function
  end interface

  ! A user's potential: phi(gap(i)), phi'(gap(i)) and, if d2phi is not null, phi''(gap(i))
  ! (d2phi points to n doubles then; reach them with c_f_pointer) for i = 1..n, in physical
  ! units; return 0 to go on, anything else to end the solve (ASP_ERR_CALLBACK).
  abstract interface
    function asp_potential_fn(n, gap, phi, dphi, d2phi, user_data) bind(c)
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: n
      real(c_double), intent(in) :: gap(n)
      real(c_double), intent(out) :: phi(n), dphi(n)
      type(c_ptr), value :: d2phi, user_data
      integer(c_int) :: asp_potential_fn
    end function
  end interface

  interface
    ! ---- errors and version ----
    function asp_status_string(status) bind(c, name='asp_status_string')
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: asp_status_string
    end function
    function asp_last_error_message() bind(c, name='asp_last_error_message')
      import :: c_ptr
      type(c_ptr) :: asp_last_error_message
    end function
    function asp_version_string() bind(c, name='asp_version_string')
      import :: c_ptr
      type(c_ptr) :: asp_version_string
    end function
    function asp_abi_version() bind(c, name='asp_abi_version')
      import :: c_int
      integer(c_int) :: asp_abi_version
    end function

    ! ---- grid ----
    subroutine asp_grid_destroy(grid) bind(c, name='asp_grid_destroy')
      import :: c_ptr
      type(c_ptr), value :: grid
    end subroutine
    function asp_grid_get_shape(grid, dimension, nx, ny, n_pixels) &
        bind(c, name='asp_grid_get_shape')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), intent(out) :: dimension
      integer(c_int64_t), intent(out) :: nx, ny, n_pixels
      integer(c_int) :: asp_grid_get_shape
    end function
    ! This process's rows of the grid: local_ny rows from row_offset on (0-based), local_pixels
    ! values in every array passed for the grid. The whole grid unless it is distributed.
    function asp_grid_get_slab(grid, local_ny, row_offset, local_pixels) &
        bind(c, name='asp_grid_get_slab')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: grid
      integer(c_int64_t), intent(out) :: local_ny, row_offset, local_pixels
      integer(c_int) :: asp_grid_get_slab
    end function
    function asp_grid_get_box(grid, lx, ly) bind(c, name='asp_grid_get_box')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(out) :: lx, ly
      integer(c_int) :: asp_grid_get_box
    end function
    function asp_grid_set_fft_planning(grid, planning) bind(c, name='asp_grid_set_fft_planning')
      import :: c_int, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), value :: planning
      integer(c_int) :: asp_grid_set_fft_planning
    end function
    function asp_grid_set_threads(grid, threads) bind(c, name='asp_grid_set_threads')
      import :: c_int, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), value :: threads
      integer(c_int) :: asp_grid_set_threads
    end function
    function asp_grid_get_threads(grid, threads) bind(c, name='asp_grid_get_threads')
      import :: c_int, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), intent(out) :: threads
      integer(c_int) :: asp_grid_get_threads
    end function

    ! ---- topographies ----

    ! ---- system ----
    function asp_system_create(grid, contact_modulus, out) bind(c, name='asp_system_create')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: contact_modulus
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_system_create
    end function
    function asp_system_create_free(grid, contact_modulus, out) &
        bind(c, name='asp_system_create_free')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: contact_modulus
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_system_create_free
    end function
    ! An elastic layer of thickness t and Poisson's ratio 0 <= nu < 0.5 on a rigid base.
    function asp_system_create_layer(grid, contact_modulus, poisson_ratio, thickness, out) &
        bind(c, name='asp_system_create_layer')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: contact_modulus, poisson_ratio, thickness
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_system_create_layer
    end function
    subroutine asp_system_destroy(system) bind(c, name='asp_system_destroy')
      import :: c_ptr
      type(c_ptr), value :: system
    end subroutine
    function asp_system_set_k0(system, k0) bind(c, name='asp_system_set_k0')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), value :: k0
      integer(c_int) :: asp_system_set_k0
    end function
    function asp_system_set_adhesion(system, work_of_adhesion, range) &
        bind(c, name='asp_system_set_adhesion')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), value :: work_of_adhesion, range
      integer(c_int) :: asp_system_set_adhesion
    end function
    function asp_system_set_soft_wall(system, gamma_r, rho_r, gamma_a, rho_a) &
        bind(c, name='asp_system_set_soft_wall')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), value :: gamma_r, rho_r, gamma_a, rho_a
      integer(c_int) :: asp_system_set_soft_wall
    end function
    function asp_system_set_lennard_jones(system, work_of_adhesion, equilibrium_distance) &
        bind(c, name='asp_system_set_lennard_jones')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), value :: work_of_adhesion, equilibrium_distance
      integer(c_int) :: asp_system_set_lennard_jones
    end function
    function asp_system_set_hard_wall(system) bind(c, name='asp_system_set_hard_wall')
      import :: c_int, c_ptr
      type(c_ptr), value :: system
      integer(c_int) :: asp_system_set_hard_wall
    end function
    ! fn: c_funloc of a procedure with the interface asp_potential_fn.
    function asp_system_set_potential(system, fn, user_data, hard_wall) &
        bind(c, name='asp_system_set_potential')
      import :: c_int, c_ptr, c_funptr
      type(c_ptr), value :: system
      type(c_funptr), value :: fn
      type(c_ptr), value :: user_data
      integer(c_int), value :: hard_wall
      integer(c_int) :: asp_system_set_potential
    end function
    function asp_system_set_reference_pressure(system, reference_pressure) &
        bind(c, name='asp_system_set_reference_pressure')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), value :: reference_pressure
      integer(c_int) :: asp_system_set_reference_pressure
    end function
    function asp_system_reset(system) bind(c, name='asp_system_reset')
      import :: c_int, c_ptr
      type(c_ptr), value :: system
      integer(c_int) :: asp_system_reset
    end function
    function asp_system_get(system, key, value) bind(c, name='asp_system_get')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: system
      integer(c_int), value :: key
      real(c_double), intent(out) :: value
      integer(c_int) :: asp_system_get
    end function

    ! ---- algorithms ----

    ! ---- solver ----
    subroutine asp_solver_destroy(solver) bind(c, name='asp_solver_destroy')
      import :: c_ptr
      type(c_ptr), value :: solver
    end subroutine
    function asp_solver_set_tolerance(solver, tolerance) bind(c, name='asp_solver_set_tolerance')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver
      real(c_double), value :: tolerance
      integer(c_int) :: asp_solver_set_tolerance
    end function
    function asp_solver_set_progress(solver, progress, user_data) &
        bind(c, name='asp_solver_set_progress')
      import :: c_int, c_funptr, c_ptr
      type(c_ptr), value :: solver
      type(c_funptr), value :: progress   ! c_funloc of an asp_progress_fn, or c_null_funptr
      type(c_ptr), value :: user_data
      integer(c_int) :: asp_solver_set_progress
    end function
    function asp_solver_set_history(solver, on) bind(c, name='asp_solver_set_history')
      import :: c_int, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), value :: on
      integer(c_int) :: asp_solver_set_history
    end function
    function asp_solver_solve(solver, system, control, value) bind(c, name='asp_solver_solve')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver, system
      integer(c_int), value :: control
      real(c_double), value :: value
      integer(c_int) :: asp_solver_solve
    end function
    function asp_solver_supports(solver, system, control) bind(c, name='asp_solver_supports')
      import :: c_int, c_ptr
      type(c_ptr), value :: solver, system
      integer(c_int), value :: control
      integer(c_int) :: asp_solver_supports
    end function
    ! The report of the last solve by key (ASP_REPORT_*), the one family to read it by; counts
    ! come as exact doubles (int(value, c_int64_t) gives them back). The getters below give
    ! the same figures one by one.
    function asp_solver_get(solver, key, value) bind(c, name='asp_solver_get')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), value :: key
      real(c_double), intent(out) :: value
      integer(c_int) :: asp_solver_get
    end function
    function asp_solver_termination(solver, reason) bind(c, name='asp_solver_termination')
      import :: c_int, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), intent(out) :: reason
      integer(c_int) :: asp_solver_termination
    end function
    function asp_solver_iterations(solver, iterations) bind(c, name='asp_solver_iterations')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), intent(out) :: iterations
      integer(c_int) :: asp_solver_iterations
    end function
    function asp_solver_evaluations(solver, evaluations) bind(c, name='asp_solver_evaluations')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), intent(out) :: evaluations
      integer(c_int) :: asp_solver_evaluations
    end function
    function asp_solver_transforms(solver, transforms) bind(c, name='asp_solver_transforms')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), intent(out) :: transforms
      integer(c_int) :: asp_solver_transforms
    end function
    function asp_solver_final_error(solver, error) bind(c, name='asp_solver_final_error')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver
      real(c_double), intent(out) :: error
      integer(c_int) :: asp_solver_final_error
    end function
    function asp_solver_converged(solver, converged) bind(c, name='asp_solver_converged')
      import :: c_int, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), intent(out) :: converged
      integer(c_int) :: asp_solver_converged
    end function
    function asp_solver_elapsed_seconds(solver, seconds) &
        bind(c, name='asp_solver_elapsed_seconds')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver
      real(c_double), intent(out) :: seconds
      integer(c_int) :: asp_solver_elapsed_seconds
    end function
    function asp_solver_history_length(solver, length) bind(c, name='asp_solver_history_length')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: asp_solver_history_length
    end function
    ! d(mean pressure)/d(penetration) of the state the solver's last, converged solve left in
    ! the system (pressure per length; see asperity.h).
    function asp_solver_normal_stiffness(solver, system, stiffness) &
        bind(c, name='asp_solver_normal_stiffness')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver, system
      real(c_double), intent(out) :: stiffness
      integer(c_int) :: asp_solver_normal_stiffness
    end function
  end interface

  ! The functions that take strings, counts or arrays: each generic interface holds the
  ! bind(c) interface (c_asp_..., private) and the module's variants of it.
  interface asp_grid_create_1d
    function c_asp_grid_create_1d(nx, lx, out) bind(c, name='asp_grid_create_1d')
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: nx
      real(c_double), value :: lx
      type(c_ptr), intent(out) :: out
      integer(c_int) :: c_asp_grid_create_1d
    end function
    module procedure grid_create_1d_int
  end interface
  interface asp_grid_create_2d
    function c_asp_grid_create_2d(nx, ny, lx, ly, out) bind(c, name='asp_grid_create_2d')
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: nx, ny
      real(c_double), value :: lx, ly
      type(c_ptr), intent(out) :: out
      integer(c_int) :: c_asp_grid_create_2d
    end function
    module procedure grid_create_2d_int
  end interface
  ! asperity_mpi.h. asp_grid_create_mpi takes a C MPI_Comm, which Fortran cannot hold; the
  ! module's asp_grid_create_mpi takes the communicator as MPI's Fortran bindings hold it (a
  ! default integer: the handle of the mpi module, or comm%MPI_VAL of mpi_f08) and calls
  ! asp_grid_create_mpi_f, which converts it in C. Only declared here, so the module compiles
  ! without MPI; a libasperity built without MPI exports asp_grid_create_mpi_f too, returning
  ! ASP_ERR_UNSUPPORTED with the reason, so programs using the module link either way.
  interface asp_grid_create_mpi_f
    function c_asp_grid_create_mpi_f(comm, nx, ny, lx, ly, out) &
        bind(c, name='asp_grid_create_mpi_f')
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int), value :: comm                ! MPI_Fint
      integer(c_int64_t), value :: nx, ny
      real(c_double), value :: lx, ly
      type(c_ptr), intent(out) :: out
      integer(c_int) :: c_asp_grid_create_mpi_f
    end function
    module procedure grid_create_mpi_int
  end interface
  interface asp_grid_create_mpi
    module procedure grid_create_mpi_int, grid_create_mpi_i64
  end interface
  interface asp_fft_export_wisdom
    function c_asp_fft_export_wisdom(path) bind(c, name='asp_fft_export_wisdom')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: c_asp_fft_export_wisdom
    end function
    module procedure fft_export_wisdom_text
  end interface
  interface asp_fft_import_wisdom
    function c_asp_fft_import_wisdom(path) bind(c, name='asp_fft_import_wisdom')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: c_asp_fft_import_wisdom
    end function
    module procedure fft_import_wisdom_text
  end interface
  interface asp_algorithms
    function c_asp_algorithms(buffer, size, length) bind(c, name='asp_algorithms')
      import :: c_int, c_int64_t, c_char
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: c_asp_algorithms
    end function
    module procedure algorithms_int, algorithms_i64
  end interface
  interface asp_solver_create
    function c_asp_solver_create(algorithm, out) bind(c, name='asp_solver_create')
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: algorithm(*)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: c_asp_solver_create
    end function
    module procedure solver_create_text
  end interface
  interface asp_solver_describe
    function c_asp_solver_describe(solver, buffer, size, length) &
        bind(c, name='asp_solver_describe')
      import :: c_int, c_int64_t, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: c_asp_solver_describe
    end function
    module procedure solver_describe_int, solver_describe_i64
  end interface
  interface asp_solver_set_option
    function c_asp_solver_set_option(solver, name, value) bind(c, name='asp_solver_set_option')
      import :: c_int, c_double, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), value :: value
      integer(c_int) :: c_asp_solver_set_option
    end function
    module procedure solver_set_option_real, solver_set_option_int, solver_set_option_i64
  end interface
  interface asp_solver_set_option_string
    function c_asp_solver_set_option_string(solver, name, value) &
        bind(c, name='asp_solver_set_option_string')
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*), value(*)
      integer(c_int) :: c_asp_solver_set_option_string
    end function
    module procedure solver_set_option_string_text
  end interface
  interface asp_solver_get_option
    function c_asp_solver_get_option(solver, name, value) bind(c, name='asp_solver_get_option')
      import :: c_int, c_double, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), intent(out) :: value
      integer(c_int) :: c_asp_solver_get_option
    end function
    module procedure solver_get_option_text
  end interface
  interface asp_solver_get_option_string
    function c_asp_solver_get_option_string(solver, name, buffer, size, length) &
        bind(c, name='asp_solver_get_option_string')
      import :: c_int, c_int64_t, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: c_asp_solver_get_option_string
    end function
    module procedure solver_get_option_string_int, solver_get_option_string_i64
  end interface
  interface asp_system_check_resolution
    function c_asp_system_check_resolution(system, ratio, resolved, buffer, size, length) &
        bind(c, name='asp_system_check_resolution')
      import :: c_int, c_int64_t, c_double, c_char, c_ptr
      type(c_ptr), value :: system
      real(c_double), intent(out) :: ratio
      integer(c_int), intent(out) :: resolved
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: c_asp_system_check_resolution
    end function
    module procedure system_check_resolution_int, system_check_resolution_i64
  end interface
  interface asp_solver_set_max_iterations
    function c_asp_solver_set_max_iterations(solver, max_iterations) &
        bind(c, name='asp_solver_set_max_iterations')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), value :: max_iterations
      integer(c_int) :: c_asp_solver_set_max_iterations
    end function
    module procedure solver_set_max_iterations_int
  end interface
  ! ---- generated by tools/generate_fortran_arrays.py: array interfaces ----
  interface asp_topography_flat
    function c_asp_topography_flat(grid, heights, n) bind(c, name='asp_topography_flat')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_flat
    end function
    module procedure topography_flat_r1_int, topography_flat_r2_int, topography_flat_r2_i64
  end interface
  interface asp_topography_sphere
    function c_asp_topography_sphere(grid, radius, heights, n) bind(c, name='asp_topography_sphere')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: radius
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_sphere
    end function
    module procedure topography_sphere_r1_int, topography_sphere_r2_int, topography_sphere_r2_i64
  end interface
  interface asp_topography_paraboloid
    function c_asp_topography_paraboloid(grid, radius, heights, n) &
        bind(c, name='asp_topography_paraboloid')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: radius
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_paraboloid
    end function
    module procedure topography_paraboloid_r1_int, topography_paraboloid_r2_int, &
        topography_paraboloid_r2_i64
  end interface
  interface asp_topography_sinusoid
    function c_asp_topography_sinusoid(grid, amplitude, periods_x, periods_y, heights, n) &
        bind(c, name='asp_topography_sinusoid')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: amplitude
      integer(c_int64_t), value :: periods_x
      integer(c_int64_t), value :: periods_y
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_sinusoid
    end function
    module procedure topography_sinusoid_r1_int, topography_sinusoid_r2_int, &
        topography_sinusoid_r2_i64
  end interface
  interface asp_topography_double_sinewave
    function c_asp_topography_double_sinewave(grid, amplitude, ripple_amplitude, ripple_periods, &
        heights, n) bind(c, name='asp_topography_double_sinewave')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: amplitude
      real(c_double), value :: ripple_amplitude
      integer(c_int64_t), value :: ripple_periods
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_double_sinewave
    end function
    module procedure topography_double_sinewave_r1_int, topography_double_sinewave_r2_int, &
        topography_double_sinewave_r2_i64
  end interface
  interface asp_topography_self_affine
    function c_asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, &
        normalise, target, seed, heights, n) bind(c, name='asp_topography_self_affine')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: hurst
      real(c_double), value :: long_cutoff
      real(c_double), value :: rolloff
      real(c_double), value :: short_cutoff
      integer(c_int), value :: normalise
      real(c_double), value :: target
      integer(c_int64_t), value :: seed
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_self_affine
    end function
    module procedure topography_self_affine_r1_int, topography_self_affine_r2_int, &
        topography_self_affine_r2_i64
  end interface
  interface asp_topography_statistics
    function c_asp_topography_statistics(grid, heights, n, rms_height, rms_slope, rms_curvature) &
        bind(c, name='asp_topography_statistics')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n
      real(c_double), intent(out) :: rms_height
      real(c_double), intent(out) :: rms_slope
      real(c_double), intent(out) :: rms_curvature
      integer(c_int) :: c_asp_topography_statistics
    end function
    module procedure topography_statistics_r1_int, topography_statistics_r2_int, &
        topography_statistics_r2_i64
  end interface
  interface asp_topography_detrend
    function c_asp_topography_detrend(grid, mode, heights, n) bind(c, name='asp_topography_detrend')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), value :: mode
      real(c_double), intent(inout) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_topography_detrend
    end function
    module procedure topography_detrend_r1_int, topography_detrend_r2_int, &
        topography_detrend_r2_i64
  end interface
  interface asp_topography_power_spectrum
    function c_asp_topography_power_spectrum(grid, heights, n, n_bins, q, c) &
        bind(c, name='asp_topography_power_spectrum')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int64_t), value :: n_bins
      real(c_double), intent(out) :: q(*)
      real(c_double), intent(out) :: c(*)
      integer(c_int) :: c_asp_topography_power_spectrum
    end function
    module procedure topography_power_spectrum_r1_int, topography_power_spectrum_r2_int, &
        topography_power_spectrum_r2_i64
  end interface
  interface asp_system_set_topography
    function c_asp_system_set_topography(system, heights, n) &
        bind(c, name='asp_system_set_topography')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_system_set_topography
    end function
    module procedure system_set_topography_r1_int, system_set_topography_r2_int, &
        system_set_topography_r2_i64
  end interface
  interface asp_system_get_field
    function c_asp_system_get_field(system, field, values, n) bind(c, name='asp_system_get_field')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: system
      integer(c_int), value :: field
      real(c_double), intent(out) :: values(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_system_get_field
    end function
    module procedure system_get_field_r1_int, system_get_field_r2_int, system_get_field_r2_i64
  end interface
  interface asp_solver_get_history
    function c_asp_solver_get_history(solver, column, values, n) &
        bind(c, name='asp_solver_get_history')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), value :: column
      real(c_double), intent(out) :: values(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: c_asp_solver_get_history
    end function
    module procedure solver_get_history_r1_int
  end interface
  ! ---- end of the generated array interfaces ----

  interface
    function c_strlen(s) bind(c, name='strlen')
      import :: c_ptr, c_int64_t
      type(c_ptr), value :: s
      integer(c_int64_t) :: c_strlen
    end function
  end interface

contains

  ! ---- text coming back ----

  ! A Fortran copy of a NUL-terminated C string (empty for a NULL pointer).
  function asp_string(s) result(text)
    type(c_ptr), intent(in) :: s
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: length
    if (.not. c_associated(s)) then
      text = ''
      return
    end if
    length = int(c_strlen(s))
    call c_f_pointer(s, chars, [length])
    text = text_of(chars, length)
  end function

  ! asp_status_string(status) as a Fortran string.
  function asp_status_text(status) result(text)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: text
    text = asp_string(asp_status_string(status))
  end function

  ! asp_last_error_message() as a Fortran string.
  function asp_last_error_text() result(text)
    character(len=:), allocatable :: text
    text = asp_string(asp_last_error_message())
  end function

  ! asp_version_string() as a Fortran string.
  function asp_version_text() result(text)
    character(len=:), allocatable :: text
    text = asp_string(asp_version_string())
  end function

  ! The text of asp_algorithms: the algorithms' names, one per line.
  function asp_algorithms_text(status) result(text)
    integer(c_int), intent(out), optional :: status
    character(len=:), allocatable :: text
    character(kind=c_char) :: probe(1)
    character(kind=c_char), allocatable :: buffer(:)
    integer(c_int64_t) :: length, buffer_size
    integer(c_int) :: stat
    text = ''
    stat = c_asp_algorithms(probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = c_asp_algorithms(buffer, buffer_size, length)
      if (stat == ASP_OK) text = text_of(buffer, int(length))
    end if
    if (present(status)) status = stat
  end function

  ! The text of asp_solver_describe: the algorithm, what it serves and its options.
  function asp_solver_describe_text(solver, status) result(text)
    type(c_ptr), intent(in) :: solver
    integer(c_int), intent(out), optional :: status
    character(len=:), allocatable :: text
    character(kind=c_char) :: probe(1)
    character(kind=c_char), allocatable :: buffer(:)
    integer(c_int64_t) :: length, buffer_size
    integer(c_int) :: stat
    text = ''
    stat = c_asp_solver_describe(solver, probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = c_asp_solver_describe(solver, buffer, buffer_size, length)
      if (stat == ASP_OK) text = text_of(buffer, int(length))
    end if
    if (present(status)) status = stat
  end function

  ! The value of a string option, by asp_solver_get_option_string.
  function asp_solver_get_option_string_text(solver, name, status) result(text)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    integer(c_int), intent(out), optional :: status
    character(len=:), allocatable :: text
    character(kind=c_char) :: probe(1)
    character(kind=c_char), allocatable :: buffer(:)
    integer(c_int64_t) :: length, buffer_size
    integer(c_int) :: stat
    text = ''
    stat = c_asp_solver_get_option_string(solver, c_string(name), probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = c_asp_solver_get_option_string(solver, c_string(name), buffer, buffer_size, length)
      if (stat == ASP_OK) text = text_of(buffer, int(length))
    end if
    if (present(status)) status = stat
  end function

  ! The sentence of asp_system_check_resolution: whether the grid resolves the system's
  ! interaction, with its ratio (the cohesive zone over the pixel size) and flag if asked.
  function asp_system_check_resolution_text(system, ratio, resolved, status) result(text)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(out), optional :: ratio
    integer(c_int), intent(out), optional :: resolved
    integer(c_int), intent(out), optional :: status
    character(len=:), allocatable :: text
    character(kind=c_char) :: probe(1)
    character(kind=c_char), allocatable :: buffer(:)
    integer(c_int64_t) :: length, buffer_size
    integer(c_int) :: stat, flag
    real(c_double) :: value
    text = ''
    value = 0
    flag = 0
    stat = c_asp_system_check_resolution(system, value, flag, probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = c_asp_system_check_resolution(system, value, flag, buffer, buffer_size, length)
      if (stat == ASP_OK) text = text_of(buffer, int(length))
    end if
    if (present(ratio)) ratio = value
    if (present(resolved)) resolved = flag
    if (present(status)) status = stat
  end function

  ! ---- default integers and Fortran strings going in ----

  function grid_create_1d_int(nx, lx, out) result(status)
    integer(c_int), intent(in) :: nx
    real(c_double), intent(in) :: lx
    type(c_ptr), intent(out) :: out
    integer(c_int) :: status
    status = c_asp_grid_create_1d(int(nx, c_int64_t), lx, out)
  end function

  function grid_create_2d_int(nx, ny, lx, ly, out) result(status)
    integer(c_int), intent(in) :: nx, ny
    real(c_double), intent(in) :: lx, ly
    type(c_ptr), intent(out) :: out
    integer(c_int) :: status
    status = c_asp_grid_create_2d(int(nx, c_int64_t), int(ny, c_int64_t), lx, ly, out)
  end function

  ! A grid shared among the processes of comm (asperity_mpi.h): collective, every process
  ! passing the same sizes and box. Each process then holds a slab of whole rows, which
  ! asp_grid_get_slab gives (local_ny rows from row_offset on, 0-based): every array it passes
  ! or receives for the grid is h(nx, local_ny), the counts local_pixels; scalar results are
  ! those of the whole grid, the same on every process; a call that fails on one process
  ! fails on all.
  function grid_create_mpi_int(comm, nx, ny, lx, ly, out) result(status)
    integer, intent(in) :: comm
    integer(c_int), intent(in) :: nx, ny
    real(c_double), intent(in) :: lx, ly
    type(c_ptr), intent(out) :: out
    integer(c_int) :: status
    status = c_asp_grid_create_mpi_f(int(comm, c_int), int(nx, c_int64_t), &
                                     int(ny, c_int64_t), lx, ly, out)
  end function

  function grid_create_mpi_i64(comm, nx, ny, lx, ly, out) result(status)
    integer, intent(in) :: comm
    integer(c_int64_t), intent(in) :: nx, ny
    real(c_double), intent(in) :: lx, ly
    type(c_ptr), intent(out) :: out
    integer(c_int) :: status
    status = c_asp_grid_create_mpi_f(int(comm, c_int), nx, ny, lx, ly, out)
  end function

  function fft_export_wisdom_text(path) result(status)
    character(len=*), intent(in) :: path
    integer(c_int) :: status
    status = c_asp_fft_export_wisdom(c_string(path))
  end function

  function fft_import_wisdom_text(path) result(status)
    character(len=*), intent(in) :: path
    integer(c_int) :: status
    status = c_asp_fft_import_wisdom(c_string(path))
  end function

  function algorithms_int(buffer, size, length) result(status)
    character(len=*), intent(out) :: buffer
    integer(c_int), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_algorithms(buffer, min(int(size, c_int64_t), len(buffer, c_int64_t)), length)
  end function

  function algorithms_i64(buffer, size, length) result(status)
    character(len=*), intent(out) :: buffer
    integer(c_int64_t), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_algorithms(buffer, min(size, len(buffer, c_int64_t)), length)
  end function

  function solver_create_text(algorithm, out) result(status)
    character(len=*), intent(in) :: algorithm
    type(c_ptr), intent(out) :: out
    integer(c_int) :: status
    status = c_asp_solver_create(c_string(algorithm), out)
  end function

  function solver_describe_int(solver, buffer, size, length) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(out) :: buffer
    integer(c_int), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_solver_describe(solver, buffer, &
                                   min(int(size, c_int64_t), len(buffer, c_int64_t)), length)
  end function

  function solver_describe_i64(solver, buffer, size, length) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(out) :: buffer
    integer(c_int64_t), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_solver_describe(solver, buffer, min(size, len(buffer, c_int64_t)), length)
  end function

  function solver_set_option_real(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = c_asp_solver_set_option(solver, c_string(name), value)
  end function

  ! Integer options given as integers: the value goes to C as the double it equals.
  function solver_set_option_int(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    integer(c_int), intent(in) :: value
    integer(c_int) :: status
    status = c_asp_solver_set_option(solver, c_string(name), real(value, c_double))
  end function

  function solver_set_option_i64(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    integer(c_int64_t), intent(in) :: value
    integer(c_int) :: status
    status = c_asp_solver_set_option(solver, c_string(name), real(value, c_double))
  end function

  function solver_set_option_string_text(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name, value
    integer(c_int) :: status
    status = c_asp_solver_set_option_string(solver, c_string(name), c_string(value))
  end function

  function solver_get_option_text(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    real(c_double), intent(out) :: value
    integer(c_int) :: status
    status = c_asp_solver_get_option(solver, c_string(name), value)
  end function

  function solver_get_option_string_int(solver, name, buffer, size, length) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    character(len=*), intent(out) :: buffer
    integer(c_int), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_solver_get_option_string(solver, c_string(name), buffer, &
                                            min(int(size, c_int64_t), len(buffer, c_int64_t)), &
                                            length)
  end function

  function solver_get_option_string_i64(solver, name, buffer, size, length) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    character(len=*), intent(out) :: buffer
    integer(c_int64_t), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_solver_get_option_string(solver, c_string(name), buffer, &
                                            min(size, len(buffer, c_int64_t)), length)
  end function

  function system_check_resolution_int(system, ratio, resolved, buffer, size, length) &
      result(status)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(out) :: ratio
    integer(c_int), intent(out) :: resolved
    character(len=*), intent(out) :: buffer
    integer(c_int), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_system_check_resolution(system, ratio, resolved, buffer, &
                                           min(int(size, c_int64_t), len(buffer, c_int64_t)), &
                                           length)
  end function

  function system_check_resolution_i64(system, ratio, resolved, buffer, size, length) &
      result(status)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(out) :: ratio
    integer(c_int), intent(out) :: resolved
    character(len=*), intent(out) :: buffer
    integer(c_int64_t), intent(in) :: size
    integer(c_int64_t), intent(out) :: length
    integer(c_int) :: status
    status = c_asp_system_check_resolution(system, ratio, resolved, buffer, &
                                           min(size, len(buffer, c_int64_t)), length)
  end function

  function solver_set_max_iterations_int(solver, max_iterations) result(status)
    type(c_ptr), intent(in) :: solver
    integer(c_int), intent(in) :: max_iterations
    integer(c_int) :: status
    status = c_asp_solver_set_max_iterations(solver, int(max_iterations, c_int64_t))
  end function

  ! ---- generated by tools/generate_fortran_arrays.py: array variants ----

  function topography_flat_r1_int(grid, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_flat(grid, heights, int(n, c_int64_t))
  end function

  function topography_flat_r2_int(grid, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_flat(grid, heights, int(n, c_int64_t))
  end function

  function topography_flat_r2_i64(grid, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_flat(grid, heights, n)
  end function

  function topography_sphere_r1_int(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sphere(grid, radius, heights, int(n, c_int64_t))
  end function

  function topography_sphere_r2_int(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sphere(grid, radius, heights, int(n, c_int64_t))
  end function

  function topography_sphere_r2_i64(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sphere(grid, radius, heights, n)
  end function

  function topography_paraboloid_r1_int(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_paraboloid(grid, radius, heights, int(n, c_int64_t))
  end function

  function topography_paraboloid_r2_int(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_paraboloid(grid, radius, heights, int(n, c_int64_t))
  end function

  function topography_paraboloid_r2_i64(grid, radius, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: radius
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_paraboloid(grid, radius, heights, n)
  end function

  function topography_sinusoid_r1_int(grid, amplitude, periods_x, periods_y, heights, &
      n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    integer(c_int), intent(in) :: periods_x
    integer(c_int), intent(in) :: periods_y
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sinusoid(grid, amplitude, int(periods_x, c_int64_t), &
        int(periods_y, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_sinusoid_r2_int(grid, amplitude, periods_x, periods_y, heights, &
      n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    integer(c_int), intent(in) :: periods_x
    integer(c_int), intent(in) :: periods_y
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sinusoid(grid, amplitude, int(periods_x, c_int64_t), &
        int(periods_y, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_sinusoid_r2_i64(grid, amplitude, periods_x, periods_y, heights, &
      n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    integer(c_int64_t), intent(in) :: periods_x
    integer(c_int64_t), intent(in) :: periods_y
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_sinusoid(grid, amplitude, periods_x, periods_y, heights, n)
  end function

  function topography_double_sinewave_r1_int(grid, amplitude, ripple_amplitude, ripple_periods, &
      heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    real(c_double), intent(in) :: ripple_amplitude
    integer(c_int), intent(in) :: ripple_periods
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_double_sinewave(grid, amplitude, ripple_amplitude, &
        int(ripple_periods, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_double_sinewave_r2_int(grid, amplitude, ripple_amplitude, ripple_periods, &
      heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    real(c_double), intent(in) :: ripple_amplitude
    integer(c_int), intent(in) :: ripple_periods
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_double_sinewave(grid, amplitude, ripple_amplitude, &
        int(ripple_periods, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_double_sinewave_r2_i64(grid, amplitude, ripple_amplitude, ripple_periods, &
      heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: amplitude
    real(c_double), intent(in) :: ripple_amplitude
    integer(c_int64_t), intent(in) :: ripple_periods
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_double_sinewave(grid, amplitude, ripple_amplitude, ripple_periods, &
        heights, n)
  end function

  function topography_self_affine_r1_int(grid, hurst, long_cutoff, rolloff, short_cutoff, &
      normalise, target, seed, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: hurst
    real(c_double), intent(in) :: long_cutoff
    real(c_double), intent(in) :: rolloff
    real(c_double), intent(in) :: short_cutoff
    integer(c_int), intent(in) :: normalise
    real(c_double), intent(in) :: target
    integer(c_int), intent(in) :: seed
    real(c_double), intent(out) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, &
        normalise, target, int(seed, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_self_affine_r2_int(grid, hurst, long_cutoff, rolloff, short_cutoff, &
      normalise, target, seed, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: hurst
    real(c_double), intent(in) :: long_cutoff
    real(c_double), intent(in) :: rolloff
    real(c_double), intent(in) :: short_cutoff
    integer(c_int), intent(in) :: normalise
    real(c_double), intent(in) :: target
    integer(c_int), intent(in) :: seed
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, &
        normalise, target, int(seed, c_int64_t), heights, int(n, c_int64_t))
  end function

  function topography_self_affine_r2_i64(grid, hurst, long_cutoff, rolloff, short_cutoff, &
      normalise, target, seed, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: hurst
    real(c_double), intent(in) :: long_cutoff
    real(c_double), intent(in) :: rolloff
    real(c_double), intent(in) :: short_cutoff
    integer(c_int), intent(in) :: normalise
    real(c_double), intent(in) :: target
    integer(c_int64_t), intent(in) :: seed
    real(c_double), intent(out) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, &
        normalise, target, seed, heights, n)
  end function

  function topography_statistics_r1_int(grid, heights, n, rms_height, rms_slope, &
      rms_curvature) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:)
    integer(c_int), intent(in) :: n
    real(c_double), intent(out) :: rms_height
    real(c_double), intent(out) :: rms_slope
    real(c_double), intent(out) :: rms_curvature
    integer(c_int) :: status
    status = c_asp_topography_statistics(grid, heights, int(n, c_int64_t), rms_height, rms_slope, &
        rms_curvature)
  end function

  function topography_statistics_r2_int(grid, heights, n, rms_height, rms_slope, &
      rms_curvature) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int), intent(in) :: n
    real(c_double), intent(out) :: rms_height
    real(c_double), intent(out) :: rms_slope
    real(c_double), intent(out) :: rms_curvature
    integer(c_int) :: status
    status = c_asp_topography_statistics(grid, heights, int(n, c_int64_t), rms_height, rms_slope, &
        rms_curvature)
  end function

  function topography_statistics_r2_i64(grid, heights, n, rms_height, rms_slope, &
      rms_curvature) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    real(c_double), intent(out) :: rms_height
    real(c_double), intent(out) :: rms_slope
    real(c_double), intent(out) :: rms_curvature
    integer(c_int) :: status
    status = c_asp_topography_statistics(grid, heights, n, rms_height, rms_slope, rms_curvature)
  end function

  function topography_detrend_r1_int(grid, mode, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    integer(c_int), intent(in) :: mode
    real(c_double), intent(inout) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_detrend(grid, mode, heights, int(n, c_int64_t))
  end function

  function topography_detrend_r2_int(grid, mode, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    integer(c_int), intent(in) :: mode
    real(c_double), intent(inout) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_detrend(grid, mode, heights, int(n, c_int64_t))
  end function

  function topography_detrend_r2_i64(grid, mode, heights, n) result(status)
    type(c_ptr), intent(in) :: grid
    integer(c_int), intent(in) :: mode
    real(c_double), intent(inout) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_topography_detrend(grid, mode, heights, n)
  end function

  function topography_power_spectrum_r1_int(grid, heights, n, n_bins, q, c) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int), intent(in) :: n_bins
    real(c_double), intent(out) :: q(*)
    real(c_double), intent(out) :: c(*)
    integer(c_int) :: status
    status = c_asp_topography_power_spectrum(grid, heights, int(n, c_int64_t), &
        int(n_bins, c_int64_t), q, c)
  end function

  function topography_power_spectrum_r2_int(grid, heights, n, n_bins, q, c) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int), intent(in) :: n_bins
    real(c_double), intent(out) :: q(*)
    real(c_double), intent(out) :: c(*)
    integer(c_int) :: status
    status = c_asp_topography_power_spectrum(grid, heights, int(n, c_int64_t), &
        int(n_bins, c_int64_t), q, c)
  end function

  function topography_power_spectrum_r2_i64(grid, heights, n, n_bins, q, c) result(status)
    type(c_ptr), intent(in) :: grid
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int64_t), intent(in) :: n_bins
    real(c_double), intent(out) :: q(*)
    real(c_double), intent(out) :: c(*)
    integer(c_int) :: status
    status = c_asp_topography_power_spectrum(grid, heights, n, n_bins, q, c)
  end function

  function system_set_topography_r1_int(system, heights, n) result(status)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(in) :: heights(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_set_topography(system, heights, int(n, c_int64_t))
  end function

  function system_set_topography_r2_int(system, heights, n) result(status)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_set_topography(system, heights, int(n, c_int64_t))
  end function

  function system_set_topography_r2_i64(system, heights, n) result(status)
    type(c_ptr), intent(in) :: system
    real(c_double), intent(in) :: heights(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_set_topography(system, heights, n)
  end function

  function system_get_field_r1_int(system, field, values, n) result(status)
    type(c_ptr), intent(in) :: system
    integer(c_int), intent(in) :: field
    real(c_double), intent(out) :: values(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_get_field(system, field, values, int(n, c_int64_t))
  end function

  function system_get_field_r2_int(system, field, values, n) result(status)
    type(c_ptr), intent(in) :: system
    integer(c_int), intent(in) :: field
    real(c_double), intent(out) :: values(:, :)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_get_field(system, field, values, int(n, c_int64_t))
  end function

  function system_get_field_r2_i64(system, field, values, n) result(status)
    type(c_ptr), intent(in) :: system
    integer(c_int), intent(in) :: field
    real(c_double), intent(out) :: values(:, :)
    integer(c_int64_t), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_system_get_field(system, field, values, n)
  end function

  function solver_get_history_r1_int(solver, column, values, n) result(status)
    type(c_ptr), intent(in) :: solver
    integer(c_int), intent(in) :: column
    real(c_double), intent(out) :: values(:)
    integer(c_int), intent(in) :: n
    integer(c_int) :: status
    status = c_asp_solver_get_history(solver, column, values, int(n, c_int64_t))
  end function
  ! ---- end of the generated array variants ----

  ! ---- private ----

  ! text for C: up to its first NUL if it has one, else without its trailing blanks and with
  ! a NUL added.
  function c_string(text) result(chars)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=:), allocatable :: chars
    integer :: nul
    nul = index(text, c_null_char)
    if (nul > 0) then
      chars = text(1:nul)
    else
      chars = trim(text)//c_null_char
    end if
  end function

  ! The first length characters of a C character array as a Fortran string.
  function text_of(chars, length) result(text)
    character(kind=c_char), intent(in) :: chars(*)
    integer, intent(in) :: length
    character(len=:), allocatable :: text
    integer :: i
    allocate (character(len=length) :: text)
    do i = 1, length
      text(i:i) = chars(i)
    end do
  end function

end module asperity
