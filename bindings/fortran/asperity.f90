! Fortran 2003 interface to asperity, through ISO_C_BINDING.
!
! Every constant and every function of include/asperity/asperity.h has a counterpart of the
! same name here (the test fortran.mirrors_header checks it). In the interfaces, handles are
! type(c_ptr), counts integer(c_int64_t), reals real(c_double), flags and statuses
! integer(c_int), callbacks type(c_funptr) (pass a bind(c) procedure with c_funloc) and their
! user data type(c_ptr) (c_loc of a variable with the target attribute, or c_null_ptr).
! Arrays are passed as ordinary Fortran arrays: a field h(nx, ny) is exactly the C layout
! (x fastest). Output arguments that C allows to be NULL are ordinary variables here.
!
! Strings going in must end in c_null_char ('pk'//c_null_char). Text coming back is either a
! C pointer, which asp_string() turns into a Fortran string, or is written into a buffer:
! a character variable (or c_char array) with its size, the length of the whole text coming
! back in length, as the header's asp_algorithms describes:
!
!   character(len=64) :: names
!   integer(c_int64_t) :: length
!   status = asp_algorithms(names, len(names, c_int64_t), length)   ! names(1:length)
!
! Helpers that spare the NUL and the buffer, not part of the C interface:
!   names ending in _f    take Fortran strings (trailing blanks are dropped, the NUL is
!                         added) and return the status of the C function of the same name
!                         without _f: asp_solver_create_f(algorithm, solver),
!                         asp_solver_set_option_f(solver, name, value),
!                         asp_solver_set_option_string_f(solver, name, value),
!                         asp_solver_get_option_f(solver, name, value),
!                         asp_fft_export_wisdom_f(path), asp_fft_import_wisdom_f(path);
!   names ending in _text return the text as an allocatable character, and take an optional
!                         status argument when the C call can fail ('' is returned then):
!                         asp_status_text(status), asp_last_error_text(),
!                         asp_version_text(), asp_algorithms_text([status]),
!                         asp_solver_describe_text(solver [, status]),
!                         asp_solver_get_option_string_text(solver, name [, status]).
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
!   status = asp_system_set_potential(system, c_funloc(my_potential), c_null_ptr, 0_c_int)
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
  integer(c_int), parameter, public :: ASP_FFT_ESTIMATE = 101, ASP_FFT_MEASURE = 102
  ! Self-affine normalisation
  integer(c_int), parameter, public :: ASP_RMS_HEIGHT = 201, ASP_RMS_SLOPE = 202
  ! Scalar results
  integer(c_int), parameter, public :: ASP_CONTACT_FRACTION = 301, ASP_MEAN_PRESSURE = 302, &
      ASP_MEAN_GAP = 303, ASP_ELASTIC_ENERGY = 304, ASP_PENETRATION = 305, ASP_TOTAL_FORCE = 306, &
      ASP_K0 = 307, ASP_REFERENCE_PRESSURE = 308, ASP_MEAN_MODE_ENERGY = 309, &
      ASP_ATTRACTIVE_FRACTION = 310, ASP_REPULSIVE_FORCE = 311, ASP_ATTRACTIVE_FORCE = 312, &
      ASP_INTERACTION_ENERGY = 313, ASP_WORK_OF_ADHESION = 314, ASP_ADHESION_RANGE = 315
  ! Fields
  integer(c_int), parameter, public :: ASP_FIELD_PRESSURE = 401, ASP_FIELD_GAP = 402, &
      ASP_FIELD_DISPLACEMENT = 403, ASP_FIELD_TOPOGRAPHY = 404
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
      ASP_TERMINATION_STALLED = 704, ASP_TERMINATION_BREAKDOWN = 705
  ! Detrending modes
  integer(c_int), parameter, public :: ASP_DETREND_MEAN = 801, ASP_DETREND_PLANE = 802, &
      ASP_DETREND_CURVATURE = 803

  public :: asp_status_string, asp_last_error_message, asp_version_string, asp_abi_version
  public :: asp_grid_create_1d, asp_grid_create_2d, asp_grid_destroy, asp_grid_get_shape, &
            asp_grid_get_box, asp_grid_set_fft_planning, asp_fft_export_wisdom, &
            asp_fft_import_wisdom
  public :: asp_topography_flat, asp_topography_sphere, asp_topography_paraboloid, &
            asp_topography_sinusoid, asp_topography_double_sinewave, &
            asp_topography_self_affine, asp_topography_statistics, asp_topography_detrend, &
            asp_topography_power_spectrum
  public :: asp_system_create, asp_system_create_free, asp_system_destroy, &
            asp_system_set_topography, &
            asp_system_set_k0, asp_system_set_adhesion, asp_system_set_soft_wall, &
            asp_system_set_lennard_jones, asp_system_set_hard_wall, asp_system_set_potential, &
            asp_system_set_reference_pressure, asp_system_reset, &
            asp_system_get, asp_system_get_field
  public :: asp_algorithms
  public :: asp_solver_create, asp_solver_destroy, asp_solver_describe, asp_solver_set_option, &
            asp_solver_set_option_string, asp_solver_get_option, asp_solver_get_option_string, &
            asp_solver_set_tolerance, asp_solver_set_max_iterations, asp_solver_set_progress, &
            asp_solver_set_history, asp_solver_solve, asp_solver_supports, &
            asp_solver_termination, &
            asp_solver_iterations, asp_solver_evaluations, asp_solver_transforms, &
            asp_solver_final_error, asp_solver_converged, &
            asp_solver_elapsed_seconds, asp_solver_history_length, asp_solver_get_history
  public :: asp_progress_fn, asp_potential_fn
  ! Helpers (see the top of this file)
  public :: asp_string
  public :: asp_status_text, asp_last_error_text, asp_version_text, asp_algorithms_text, &
            asp_solver_describe_text, asp_solver_get_option_string_text
  public :: asp_solver_create_f, asp_solver_set_option_f, asp_solver_set_option_string_f, &
            asp_solver_get_option_f, asp_fft_export_wisdom_f, asp_fft_import_wisdom_f

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
    function asp_grid_create_1d(nx, lx, out) bind(c, name='asp_grid_create_1d')
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: nx
      real(c_double), value :: lx
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_grid_create_1d
    end function
    function asp_grid_create_2d(nx, ny, lx, ly, out) bind(c, name='asp_grid_create_2d')
      import :: c_int, c_int64_t, c_double, c_ptr
      integer(c_int64_t), value :: nx, ny
      real(c_double), value :: lx, ly
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_grid_create_2d
    end function
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
    function asp_fft_export_wisdom(path) bind(c, name='asp_fft_export_wisdom')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: asp_fft_export_wisdom
    end function
    function asp_fft_import_wisdom(path) bind(c, name='asp_fft_import_wisdom')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: asp_fft_import_wisdom
    end function

    ! ---- topographies ----
    function asp_topography_flat(grid, heights, n) bind(c, name='asp_topography_flat')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_flat
    end function
    function asp_topography_sphere(grid, radius, heights, n) &
        bind(c, name='asp_topography_sphere')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: radius
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_sphere
    end function
    function asp_topography_paraboloid(grid, radius, heights, n) &
        bind(c, name='asp_topography_paraboloid')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: radius
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_paraboloid
    end function
    function asp_topography_sinusoid(grid, amplitude, periods_x, periods_y, heights, n) &
        bind(c, name='asp_topography_sinusoid')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: amplitude
      integer(c_int64_t), value :: periods_x, periods_y
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_sinusoid
    end function
    function asp_topography_double_sinewave(grid, amplitude, ripple_amplitude, ripple_periods, &
        heights, n) bind(c, name='asp_topography_double_sinewave')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: amplitude, ripple_amplitude
      integer(c_int64_t), value :: ripple_periods
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_double_sinewave
    end function
    function asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, &
        normalise, target, seed, heights, n) bind(c, name='asp_topography_self_affine')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), value :: hurst, long_cutoff, rolloff, short_cutoff
      integer(c_int), value :: normalise
      real(c_double), value :: target
      integer(c_int64_t), value :: seed
      real(c_double), intent(out) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_self_affine
    end function
    function asp_topography_detrend(grid, mode, heights, n) &
        bind(c, name='asp_topography_detrend')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      integer(c_int), value :: mode
      real(c_double), intent(inout) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_topography_detrend
    end function
    function asp_topography_statistics(grid, heights, n, rms_height, rms_slope, rms_curvature) &
        bind(c, name='asp_topography_statistics')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n
      real(c_double), intent(out) :: rms_height, rms_slope, rms_curvature
      integer(c_int) :: asp_topography_statistics
    end function
    function asp_topography_power_spectrum(grid, heights, n, n_bins, q, c) &
        bind(c, name='asp_topography_power_spectrum')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: grid
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n, n_bins
      real(c_double), intent(out) :: q(*), c(*)
      integer(c_int) :: asp_topography_power_spectrum
    end function

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
    subroutine asp_system_destroy(system) bind(c, name='asp_system_destroy')
      import :: c_ptr
      type(c_ptr), value :: system
    end subroutine
    function asp_system_set_topography(system, heights, n) &
        bind(c, name='asp_system_set_topography')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: system
      real(c_double), intent(in) :: heights(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_system_set_topography
    end function
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
    function asp_system_get_field(system, field, values, n) bind(c, name='asp_system_get_field')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: system
      integer(c_int), value :: field
      real(c_double), intent(out) :: values(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_system_get_field
    end function

    ! ---- algorithms ----
    function asp_algorithms(buffer, size, length) bind(c, name='asp_algorithms')
      import :: c_int, c_int64_t, c_char
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: asp_algorithms
    end function

    ! ---- solver ----
    function asp_solver_create(algorithm, out) bind(c, name='asp_solver_create')
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: algorithm(*)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: asp_solver_create
    end function
    subroutine asp_solver_destroy(solver) bind(c, name='asp_solver_destroy')
      import :: c_ptr
      type(c_ptr), value :: solver
    end subroutine
    function asp_solver_describe(solver, buffer, size, length) &
        bind(c, name='asp_solver_describe')
      import :: c_int, c_int64_t, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: asp_solver_describe
    end function
    function asp_solver_set_option(solver, name, value) bind(c, name='asp_solver_set_option')
      import :: c_int, c_double, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), value :: value
      integer(c_int) :: asp_solver_set_option
    end function
    function asp_solver_set_option_string(solver, name, value) &
        bind(c, name='asp_solver_set_option_string')
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*), value(*)
      integer(c_int) :: asp_solver_set_option_string
    end function
    function asp_solver_get_option(solver, name, value) bind(c, name='asp_solver_get_option')
      import :: c_int, c_double, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      real(c_double), intent(out) :: value
      integer(c_int) :: asp_solver_get_option
    end function
    function asp_solver_get_option_string(solver, name, buffer, size, length) &
        bind(c, name='asp_solver_get_option_string')
      import :: c_int, c_int64_t, c_char, c_ptr
      type(c_ptr), value :: solver
      character(kind=c_char), intent(in) :: name(*)
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int64_t), value :: size
      integer(c_int64_t), intent(out) :: length
      integer(c_int) :: asp_solver_get_option_string
    end function
    function asp_solver_set_tolerance(solver, tolerance) bind(c, name='asp_solver_set_tolerance')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: solver
      real(c_double), value :: tolerance
      integer(c_int) :: asp_solver_set_tolerance
    end function
    function asp_solver_set_max_iterations(solver, max_iterations) &
        bind(c, name='asp_solver_set_max_iterations')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: solver
      integer(c_int64_t), value :: max_iterations
      integer(c_int) :: asp_solver_set_max_iterations
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
    function asp_solver_get_history(solver, column, values, n) &
        bind(c, name='asp_solver_get_history')
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: solver
      integer(c_int), value :: column
      real(c_double), intent(out) :: values(*)
      integer(c_int64_t), value :: n
      integer(c_int) :: asp_solver_get_history
    end function
  end interface

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
    stat = asp_algorithms(probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = asp_algorithms(buffer, buffer_size, length)
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
    stat = asp_solver_describe(solver, probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = asp_solver_describe(solver, buffer, buffer_size, length)
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
    stat = asp_solver_get_option_string(solver, c_string(name), probe, 0_c_int64_t, length)
    if (stat == ASP_OK) then
      buffer_size = length + 1
      allocate (buffer(buffer_size))
      stat = asp_solver_get_option_string(solver, c_string(name), buffer, buffer_size, length)
      if (stat == ASP_OK) text = text_of(buffer, int(length))
    end if
    if (present(status)) status = stat
  end function

  ! ---- Fortran strings going in ----

  function asp_solver_create_f(algorithm, solver) result(status)
    character(len=*), intent(in) :: algorithm
    type(c_ptr), intent(out) :: solver
    integer(c_int) :: status
    status = asp_solver_create(c_string(algorithm), solver)
  end function

  function asp_solver_set_option_f(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = asp_solver_set_option(solver, c_string(name), value)
  end function

  function asp_solver_set_option_string_f(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name, value
    integer(c_int) :: status
    status = asp_solver_set_option_string(solver, c_string(name), c_string(value))
  end function

  function asp_solver_get_option_f(solver, name, value) result(status)
    type(c_ptr), intent(in) :: solver
    character(len=*), intent(in) :: name
    real(c_double), intent(out) :: value
    integer(c_int) :: status
    status = asp_solver_get_option(solver, c_string(name), value)
  end function

  function asp_fft_export_wisdom_f(path) result(status)
    character(len=*), intent(in) :: path
    integer(c_int) :: status
    status = asp_fft_export_wisdom(c_string(path))
  end function

  function asp_fft_import_wisdom_f(path) result(status)
    character(len=*), intent(in) :: path
    integer(c_int) :: status
    status = asp_fft_import_wisdom(c_string(path))
  end function

  ! ---- private ----

  ! text without its trailing blanks, NUL-terminated for C.
  function c_string(text) result(chars)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=len_trim(text) + 1) :: chars
    chars = trim(text)//c_null_char
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
