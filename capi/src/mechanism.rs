//! The registered mechanisms for C: their names, and for one looked up by name and
//! formulation its sizes, sparsity patterns, initial pose, driver names and generated
//! equations, evaluated into the caller's buffers.

use crate::status::{arg, arg_mut, guard, guard_value, input, output, string, Failure};
use crate::status::{SymbodyFormulation, SymbodyStatus};
use std::collections::HashMap;
use std::ffi::{c_char, c_int, CString};
use std::path::Path;
use std::sync::{Mutex, OnceLock};
use symbody::files;
use symbody::session::Dyn;
use symbody_mechanisms::REGISTRY;
use symbody_runtime::{Entry, Formulation, JointKind, MechanismInfo, Origin};

/// One generated mechanism in one formulation (opaque). Made by `symbody_mechanism_new` or
/// `symbody_session_mechanism`, released by `symbody_mechanism_free`. It holds no state:
/// every function taking a `const SymbodyMechanism*` may be called from any thread.
pub struct SymbodyMechanism {
    pub(crate) mech: Dyn,
    /// NUL-terminated driver names, in `symbody_session_driver_efforts` order.
    driver_names: Vec<CString>,
    /// The file the equations are interpreted from; `None` for compiled code.
    source: Option<CString>,
}

impl SymbodyMechanism {
    pub(crate) fn new(mech: Dyn, source: Option<CString>) -> SymbodyMechanism {
        let driver_names = mech
            .info()
            .joints
            .iter()
            .filter(|j| j.kind == JointKind::Driver)
            .map(|j| CString::new(j.name).expect("generated names have no NUL"))
            .collect();
        SymbodyMechanism {
            mech,
            driver_names,
            source,
        }
    }

    fn info(&self) -> &'static MechanismInfo {
        self.mech.info()
    }
}

/// The formulation code `f` as `None` (default) or a formulation.
pub(crate) fn formulation(f: c_int) -> Result<Option<Formulation>, Failure> {
    match f {
        f if f == SymbodyFormulation::Default as c_int => Ok(None),
        f if f == SymbodyFormulation::Paper as c_int => Ok(Some(Formulation::Paper)),
        f if f == SymbodyFormulation::Exact as c_int => Ok(Some(Formulation::Exact)),
        _ => Err(Failure::new(
            SymbodyStatus::InvalidArgument,
            format!("formulation {f} is none of 0 (default), 1 (paper), 2 (exact)"),
        )),
    }
}

/// The mechanism file at `path`, interpreted, with the file statuses: `FileNotFound` when
/// nothing readable is there (missing, a folder, no permission), `InvalidFile` when its
/// contents are no mechanism.
pub(crate) fn load_file(path: &str) -> Result<&'static Entry, Failure> {
    let p = Path::new(path);
    if path.is_empty() {
        return Err(Failure::new(
            SymbodyStatus::FileNotFound,
            "mechanism file ``: the path is empty",
        ));
    }
    files::load(p).map(|l| l.entry).map_err(|e| {
        // The library's messages name the path and say which case it is; the status only
        // sorts them (the metadata read again, after the failure).
        let unreadable = std::fs::metadata(p).map_or(true, |m| m.is_dir());
        let status = if unreadable {
            SymbodyStatus::FileNotFound
        } else {
            SymbodyStatus::InvalidFile
        };
        Failure::new(status, e.to_string())
    })
}

/// The entry `name` names: a file when it ends in `.toml` or has a folder
/// (`symbody::files::is_path`), else a registered mechanism (interpreted from its file when
/// that changed after its code was generated).
pub(crate) fn find(name: &str) -> Result<&'static Entry, Failure> {
    if files::is_path(name) {
        return load_file(name);
    }
    // A registered name fails only when its changed file no longer loads.
    let status = if REGISTRY.find(name).is_some() {
        SymbodyStatus::InvalidFile
    } else {
        SymbodyStatus::UnknownName
    };
    symbody::generic::find(&REGISTRY, name).map_err(|e| Failure::from_session(e, status))
}

/// `entry`'s mechanism in formulation code `f`.
pub(crate) fn pick(entry: &'static Entry, f: c_int) -> Result<Dyn, Failure> {
    let f = formulation(f)?;
    symbody::generic::mechanism(entry, f)
        .map_err(|e| Failure::from_session(e, SymbodyStatus::InvalidArgument))
}

/// An entry and its mechanism in one formulation, or why not.
pub(crate) type Found = Result<(&'static Entry, Dyn), Failure>;

/// What `name` names (see [`find`]) in formulation code `f`.
pub(crate) fn lookup(name: &str, f: c_int) -> Found {
    // The formulation code is checked before anything is read.
    formulation(f)?;
    let entry = find(name)?;
    Ok((entry, pick(entry, f)?))
}

/// The mechanism file at `path` (whatever its name) in formulation code `f`.
pub(crate) fn lookup_file(path: &str, f: c_int) -> Found {
    formulation(f)?;
    let entry = load_file(path)?;
    Ok((entry, pick(entry, f)?))
}

/// `count` parameters of a mechanism file, `names[i]` set to `values[i]`.
///
/// # Safety
/// When `count > 0`, `names` and `values` point to `count` readable entries, each name NULL
/// or a NUL-terminated string.
pub(crate) unsafe fn parameters(
    names: *const *const c_char,
    values: *const f64,
    count: usize,
) -> Result<Vec<(String, f64)>, Failure> {
    if count == 0 {
        return Ok(Vec::new());
    }
    // SAFETY: the caller's contract.
    let (names, values) = unsafe {
        (
            crate::status::input(names, count, count, "names")?,
            crate::status::input(values, count, count, "values")?,
        )
    };
    names
        .iter()
        .zip(values)
        .enumerate()
        .map(|(i, (&n, &v))| {
            // SAFETY: the caller's contract.
            let n = unsafe { string(n, &format!("names[{i}]"))? };
            Ok((n.to_string(), v))
        })
        .collect()
}

/// What `name` names (see [`find`]) with `params` set, in formulation code `f`. A bad name
/// or value is `InvalidArgument`, with the file's diagnostics.
pub(crate) fn lookup_with(name: &str, f: c_int, params: &[(String, f64)]) -> Found {
    formulation(f)?;
    let entry = find(name)?;
    let entry = match params.is_empty() {
        true => entry,
        false => files::reparametrized(entry, params)
            .map_err(|e| Failure::from_session(e, SymbodyStatus::InvalidArgument))?,
    };
    Ok((entry, pick(entry, f)?))
}

/// As `symbody_mechanism_new`, with parameters of the mechanism's file (its `[parameters]`)
/// set before anything is derived: `names[i]` to `values[i]` for `i < count` (`count` 0:
/// none), as if the file said so, as `symbody simulate --set` does. Nothing is compiled: the
/// compiled code takes the numbers the file gives at these values (the file's equations run
/// interpreted where the values change what the code holds fixed); the initial pose is
/// assembled again, and the dependent rows, degrees of freedom and platform found again.
///
/// Errors: those of `symbody_mechanism_new`, and `SYMBODY_STATUS_INVALID_ARGUMENT` for an
/// unknown parameter (the message suggests the closest), a value that is not finite, or
/// values the mechanism cannot be built with (a negative mass, a pose that cannot be
/// assembled: the message names the parameters and what they broke).
///
/// # Safety
/// As `symbody_mechanism_new`; when `count > 0`, `names` and `values` point to `count`
/// readable entries and each name is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_with_parameters(
    name: *const c_char,
    formulation: c_int,
    names: *const *const c_char,
    values: *const f64,
    count: usize,
    out: *mut *mut SymbodyMechanism,
) -> c_int {
    let find = |what: &str, f: c_int| {
        // SAFETY: the caller's contract.
        let params = unsafe { parameters(names, values, count)? };
        lookup_with(what, f, &params)
    };
    // SAFETY: the same contract.
    unsafe { new_handle(name, "name", formulation, out, &find) }
}

/// The `[parameters]` of the file of mechanism `name` (see [`find`]), in name order, each
/// name NUL-terminated with its value in the file; read once per name and kept for the
/// program (C holds the names).
fn file_parameters(name: &str) -> Result<&'static [(CString, f64)], Failure> {
    type Listed = HashMap<String, &'static [(CString, f64)]>;
    static LISTED: OnceLock<Mutex<Listed>> = OnceLock::new();
    let listed = LISTED.get_or_init(Default::default);
    if let Some(&l) = listed.lock().unwrap_or_else(|e| e.into_inner()).get(name) {
        return Ok(l);
    }
    find(name)?;
    let loaded = files::parameters(&REGISTRY, name)
        .map_err(|e| Failure::from_session(e, SymbodyStatus::InvalidArgument))?;
    let list: Vec<(CString, f64)> = loaded
        .parameters
        .iter()
        // A TOML key with a NUL is no parameter anyone could set from C.
        .filter_map(|p| Some((CString::new(p.name.as_str()).ok()?, p.value)))
        .collect();
    let list: &'static [(CString, f64)] = Box::leak(list.into_boxed_slice());
    listed
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(name.to_string(), list);
    Ok(list)
}

/// Stores in `*count` how many parameters (`[parameters]` entries) the file of mechanism
/// `name` has (a registered name or a mechanism file, as for `symbody_mechanism_new`); they
/// are numbered 0 … count − 1 in name order (`symbody_parameter`), and set by name with
/// `symbody_mechanism_with_parameters` or `symbody_session_with_parameters`.
///
/// Errors: those of `symbody_mechanism_new` for `name`.
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `count` is NULL or points to a writable
/// `size_t`.
#[no_mangle]
pub unsafe extern "C" fn symbody_parameter_count(name: *const c_char, count: *mut usize) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let (name, count) = unsafe { (string(name, "name")?, arg_mut(count, "count")?) };
        *count = file_parameters(name)?.len();
        Ok(())
    })
}

/// Parameter `i` (0-based, in name order) of the file of mechanism `name`: its name in
/// `*parameter` (NUL-terminated, valid for the program's life) and its value in the file in
/// `*value`.
///
/// Errors: those of `symbody_parameter_count`, and `SYMBODY_STATUS_INVALID_ARGUMENT` when `i`
/// is not below the count.
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `parameter` and `value` are NULL or point to
/// writable storage for one pointer and one `double`.
#[no_mangle]
pub unsafe extern "C" fn symbody_parameter(
    name: *const c_char,
    i: usize,
    parameter: *mut *const c_char,
    value: *mut f64,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let (name, parameter, value) = unsafe {
            (
                string(name, "name")?,
                arg_mut(parameter, "parameter")?,
                arg_mut(value, "value")?,
            )
        };
        let list = file_parameters(name)?;
        let (n, v) = list.get(i).ok_or_else(|| {
            Failure::new(
                SymbodyStatus::InvalidArgument,
                format!("parameter index {i}: `{name}` has {}", list.len()),
            )
        })?;
        *parameter = n.as_ptr();
        *value = *v;
        Ok(())
    })
}

/// The file `entry`'s equations are interpreted from, NUL-terminated; `None` for compiled
/// code.
pub(crate) fn source(entry: &Entry) -> Option<CString> {
    match entry.origin {
        Origin::Compiled { .. } => None,
        // A path has no NUL (it came through a C string or the file system).
        Origin::Interpreted { file, .. } => CString::new(file).ok(),
    }
}

fn names() -> &'static [CString] {
    static NAMES: OnceLock<Vec<CString>> = OnceLock::new();
    NAMES.get_or_init(|| {
        REGISTRY
            .iter()
            .map(|e| CString::new(e.name).expect("generated names have no NUL"))
            .collect()
    })
}

/// Number of registered mechanisms.
#[no_mangle]
pub extern "C" fn symbody_mechanism_count() -> usize {
    guard_value(0, || Ok(REGISTRY.len()))
}

/// Name of registered mechanism `i` (0-based, below `symbody_mechanism_count()`), a static
/// NUL-terminated string; NULL (with an error message) if `i` is out of range.
#[no_mangle]
pub extern "C" fn symbody_mechanism_name(i: usize) -> *const c_char {
    guard_value(std::ptr::null(), || {
        names().get(i).map(|n| n.as_ptr()).ok_or_else(|| {
            Failure::new(
                SymbodyStatus::InvalidArgument,
                format!("mechanism index {i}: there are {}", REGISTRY.len()),
            )
        })
    })
}

/// Looks up the registered mechanism `name` in `formulation` (a `SymbodyFormulation`) and
/// stores a new handle in `*out` (NULL on failure). Release it with
/// `symbody_mechanism_free`.
///
/// `name` may also be the path of a mechanism file (one ending in `.toml` or with a folder,
/// e.g. `"robots/arm.toml"`): the file is read and its equations run interpreted, nothing
/// compiled (see `symbody_mechanism_from_file`). A registered mechanism whose file changed
/// since its code was generated runs interpreted from the changed file, never as the stale
/// code; `symbody_mechanism_source` tells which.
///
/// Errors: `SYMBODY_STATUS_UNKNOWN_NAME` (the message lists the registered names),
/// `SYMBODY_STATUS_INVALID_ARGUMENT` for a bad formulation code or one the mechanism was
/// not generated in, and for a file those of `symbody_mechanism_from_file`.
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `out` is NULL or points to writable storage
/// for one pointer.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_new(
    name: *const c_char,
    formulation: c_int,
    out: *mut *mut SymbodyMechanism,
) -> c_int {
    // SAFETY: the same contract.
    unsafe { new_handle(name, "name", formulation, out, &lookup) }
}

/// Reads the mechanism file at `path` (always a path, whatever its name: `"arm"` is the
/// file `arm` in the working directory, not a registered mechanism), derives its equations
/// and stores a handle to them, interpreted in `formulation`, in `*out` (NULL on failure).
/// Nothing is compiled; the numbers are those the generated code of the same file computes,
/// to rounding. Each distinct file text is derived once per process and kept until it ends.
/// Release the handle with `symbody_mechanism_free`.
///
/// Errors: `SYMBODY_STATUS_FILE_NOT_FOUND` (nothing readable at `path`: missing, a folder,
/// no permission), `SYMBODY_STATUS_INVALID_FILE` (not UTF-8 text, too large, a TOML or
/// modelling error: the message names the file and gives each diagnostic's line:column),
/// `SYMBODY_STATUS_INVALID_ARGUMENT` (a bad formulation code, one the file does not list, or
/// a `path` that is not UTF-8).
///
/// # Safety
/// `path` is NULL or a NUL-terminated string; `out` is NULL or points to writable storage
/// for one pointer.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_from_file(
    path: *const c_char,
    formulation: c_int,
    out: *mut *mut SymbodyMechanism,
) -> c_int {
    // SAFETY: the same contract.
    unsafe { new_handle(path, "path", formulation, out, &lookup_file) }
}

/// Stores in `*out` a handle to what `what` names, resolved by `find`.
///
/// # Safety
/// As for `symbody_mechanism_new`.
unsafe fn new_handle(
    what: *const c_char,
    arg_name: &str,
    formulation: c_int,
    out: *mut *mut SymbodyMechanism,
    find: &dyn Fn(&str, c_int) -> Found,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above.
        let out = unsafe { arg_mut(out, "out")? };
        *out = std::ptr::null_mut();
        // SAFETY: the caller's contract above.
        let what = unsafe { string(what, arg_name)? };
        let (entry, mech) = find(what, formulation)?;
        *out = Box::into_raw(Box::new(SymbodyMechanism::new(mech, source(entry))));
        Ok(())
    })
}

/// The file the handle's equations are interpreted from (as given, NUL-terminated, valid
/// until `m` is freed), or NULL when they are compiled code, or if `m` is NULL (then with an
/// error message).
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_source(m: *const SymbodyMechanism) -> *const c_char {
    guard_value(std::ptr::null(), || {
        // SAFETY: the caller's contract.
        let m = unsafe { arg(m, "mechanism")? };
        Ok(m.source.as_ref().map_or(std::ptr::null(), |s| s.as_ptr()))
    })
}

/// Releases a mechanism handle; NULL is ignored.
///
/// # Safety
/// `m` is NULL or a handle from this library not yet freed; it is not used afterwards.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_free(m: *mut SymbodyMechanism) {
    guard_value((), || {
        if !m.is_null() {
            // SAFETY: made by Box::into_raw and, by the caller's contract, not yet freed.
            drop(unsafe { Box::from_raw(m) });
        }
        Ok(())
    })
}

/// Runs `f` on the handle's info; `fallback` (and an error message) if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
unsafe fn size<T>(
    m: *const SymbodyMechanism,
    fallback: T,
    f: impl FnOnce(&SymbodyMechanism) -> T,
) -> T {
    guard_value(fallback, || {
        // SAFETY: the caller's contract.
        Ok(f(unsafe { arg(m, "mechanism")? }))
    })
}

/// Number of coordinates `q` (and of velocities `qd`); 0 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_n_coords(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().n_coords) }
}

/// Number of constraint rows (entries of Φ, γ and the multipliers); 0 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_n_constraints(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().n_constraints) }
}

/// Number of structural nonzeros of the constraint Jacobian Φq; 0 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_phi_q_nnz(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().phi_q_nnz()) }
}

/// Number of structural nonzeros of the (symmetric, both triangles stored) mass matrix;
/// 0 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_mass_nnz(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().mass_nnz()) }
}

/// Number of structural nonzeros of the applied loads' ∂Q/∂q (springs, dampers,
/// actuators, applied forces; not gravity or the inertial terms): 0 for a mechanism without
/// such loads, or if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_force_q_nnz(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().force_q_rows.len()) }
}

/// Number of structural nonzeros of the applied loads' ∂Q/∂q̇; 0 for a mechanism without
/// such loads, or if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_force_qd_nnz(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.info().force_qd_rows.len()) }
}

/// The handle's formulation: `SYMBODY_FORMULATION_PAPER` or `SYMBODY_FORMULATION_EXACT`
/// (never `_DEFAULT`: that resolves to one of them); -1 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_formulation(m: *const SymbodyMechanism) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        size(m, -1, |m| match m.info().formulation {
            Formulation::Paper => SymbodyFormulation::Paper as c_int,
            Formulation::Exact => SymbodyFormulation::Exact as c_int,
        })
    }
}

/// Number of drivers (entries of `symbody_session_driver_efforts`); 0 if `m` is NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_driver_count(m: *const SymbodyMechanism) -> usize {
    // SAFETY: the caller's contract.
    unsafe { size(m, 0, |m| m.driver_names.len()) }
}

/// Name of driver `i` (0-based, in `symbody_session_driver_efforts` order), NUL-terminated
/// and valid until `m` is freed; NULL (with an error message) if `m` is NULL or `i` is out
/// of range.
///
/// # Safety
/// `m` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_driver_name(
    m: *const SymbodyMechanism,
    i: usize,
) -> *const c_char {
    guard_value(std::ptr::null(), || {
        // SAFETY: the caller's contract.
        let m = unsafe { arg(m, "mechanism")? };
        m.driver_names.get(i).map(|n| n.as_ptr()).ok_or_else(|| {
            Failure::new(
                SymbodyStatus::InvalidArgument,
                format!(
                    "driver index {i}: `{}` has {} drivers",
                    m.info().name,
                    m.driver_names.len()
                ),
            )
        })
    })
}

/// Copies a sparsity pattern into the caller's buffers.
///
/// # Safety
/// As for the public pattern functions.
unsafe fn pattern(
    m: *const SymbodyMechanism,
    rows: *mut u32,
    cols: *mut u32,
    len: usize,
    which: fn(&MechanismInfo) -> (&'static [u32], &'static [u32]),
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let m = unsafe { arg(m, "mechanism")? };
        let (r, c) = which(m.info());
        // SAFETY: the caller's contract; lengths checked inside.
        let rows = unsafe { output(rows, len, r.len(), "rows")? };
        // SAFETY: as above.
        let cols = unsafe { output(cols, len, c.len(), "cols")? };
        rows.copy_from_slice(r);
        cols.copy_from_slice(c);
        Ok(())
    })
}

/// Copies the Φq sparsity pattern: the 0-based row and column of each structural nonzero,
/// in the order `symbody_mechanism_phi_q` writes the values (row-major, columns
/// ascending). `rows` and `cols` each hold `len >= symbody_mechanism_phi_q_nnz(m)` entries.
///
/// # Safety
/// `m` is NULL or a live handle; `rows` and `cols` are NULL or point to `len` writable
/// `uint32_t` each.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_phi_q_pattern(
    m: *const SymbodyMechanism,
    rows: *mut u32,
    cols: *mut u32,
    len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe { pattern(m, rows, cols, len, |i| (i.phi_q_rows, i.phi_q_cols)) }
}

/// Copies the mass matrix's sparsity pattern (both triangles), in the order
/// `symbody_mechanism_mass` writes the values. `rows` and `cols` each hold
/// `len >= symbody_mechanism_mass_nnz(m)` entries.
///
/// # Safety
/// `m` is NULL or a live handle; `rows` and `cols` are NULL or point to `len` writable
/// `uint32_t` each.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_mass_pattern(
    m: *const SymbodyMechanism,
    rows: *mut u32,
    cols: *mut u32,
    len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe { pattern(m, rows, cols, len, |i| (i.mass_rows, i.mass_cols)) }
}

/// Copies the sparsity pattern of the loads' ∂Q/∂q (row-major), in the order
/// `symbody_mechanism_force_jacobian` writes `dq`. `rows` and `cols` each hold
/// `len >= symbody_mechanism_force_q_nnz(m)` entries.
///
/// # Safety
/// `m` is NULL or a live handle; `rows` and `cols` are NULL or point to `len` writable
/// `uint32_t` each.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_force_q_pattern(
    m: *const SymbodyMechanism,
    rows: *mut u32,
    cols: *mut u32,
    len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe { pattern(m, rows, cols, len, |i| (i.force_q_rows, i.force_q_cols)) }
}

/// Copies the sparsity pattern of the loads' ∂Q/∂q̇ (row-major), in the order
/// `symbody_mechanism_force_jacobian` writes `dqd`. `rows` and `cols` each hold
/// `len >= symbody_mechanism_force_qd_nnz(m)` entries.
///
/// # Safety
/// `m` is NULL or a live handle; `rows` and `cols` are NULL or point to `len` writable
/// `uint32_t` each.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_force_qd_pattern(
    m: *const SymbodyMechanism,
    rows: *mut u32,
    cols: *mut u32,
    len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe { pattern(m, rows, cols, len, |i| (i.force_qd_rows, i.force_qd_cols)) }
}

/// Copies the initial coordinates (the mechanism file's pose, assembled) into `out`, which
/// holds `out_len >= symbody_mechanism_n_coords(m)` entries.
///
/// # Safety
/// `m` is NULL or a live handle; `out` is NULL or points to `out_len` writable doubles.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_q0(
    m: *const SymbodyMechanism,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let m = unsafe { arg(m, "mechanism")? };
        let q0 = m.info().q0;
        // SAFETY: the caller's contract; length checked inside.
        unsafe { output(out, out_len, q0.len(), "out")? }.copy_from_slice(q0);
        Ok(())
    })
}

/// The inputs and output of one evaluation, checked.
struct Eval<'a> {
    mech: Dyn,
    q: &'a [f64],
    qd: &'a [f64],
    out: &'a mut [f64],
}

/// Checks an evaluation's arguments (`qd` may be absent) and runs `f` on them.
///
/// # Safety
/// As for the public evaluation functions.
#[allow(clippy::too_many_arguments)]
unsafe fn eval(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    qd: Option<(*const f64, usize)>,
    out: *mut f64,
    out_len: usize,
    out_size: fn(&MechanismInfo) -> usize,
    f: impl FnOnce(Eval<'_>),
) -> c_int {
    guard(|| {
        // SAFETY (all four): the caller's contract; lengths checked inside.
        let m = unsafe { arg(m, "mechanism")? };
        let info = m.info();
        let q = unsafe { input(q, q_len, info.n_coords, "q")? };
        let qd = match qd {
            Some((p, len)) => unsafe { input(p, len, info.n_coords, "qd")? },
            None => &[],
        };
        let out = unsafe { output(out, out_len, out_size(info), "out")? };
        f(Eval {
            mech: m.mech,
            q,
            qd,
            out,
        });
        Ok(())
    })
}

/// Evaluates the constraint residual Φ(q, t) into `out` (`symbody_mechanism_n_constraints`
/// entries). `q` holds `q_len >= symbody_mechanism_n_coords(m)` entries; longer buffers
/// are fine (the extra entries are ignored or left alone).
///
/// # Safety
/// `m` is NULL or a live handle; `q` is NULL or points to `q_len` readable doubles; `out`
/// is NULL or points to `out_len` writable doubles not overlapping `q`.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_phi(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    t: f64,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        eval(
            m,
            q,
            q_len,
            None,
            out,
            out_len,
            |i| i.n_constraints,
            |e| e.mech.phi(e.q, t, e.out),
        )
    }
}

/// Evaluates the constraint Jacobian's nonzeros Φq(q, t) into `out`
/// (`symbody_mechanism_phi_q_nnz` entries, in `symbody_mechanism_phi_q_pattern` order).
///
/// # Safety
/// `m` is NULL or a live handle; `q` is NULL or points to `q_len` readable doubles; `out`
/// is NULL or points to `out_len` writable doubles not overlapping `q`.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_phi_q(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    t: f64,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        eval(
            m,
            q,
            q_len,
            None,
            out,
            out_len,
            |i| i.phi_q_nnz(),
            |e| e.mech.phi_q(e.q, t, e.out),
        )
    }
}

/// Evaluates the acceleration right-hand side γ(q, q̇, t) = −(Φq q̇)q q̇ − 2Φqt q̇ − Φtt
/// into `out` (`symbody_mechanism_n_constraints` entries).
///
/// # Safety
/// `m` is NULL or a live handle; `q` and `qd` are NULL or point to `q_len` and `qd_len`
/// readable doubles; `out` is NULL or points to `out_len` writable doubles not overlapping
/// the inputs.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn symbody_mechanism_gamma(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    qd: *const f64,
    qd_len: usize,
    t: f64,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        eval(
            m,
            q,
            q_len,
            Some((qd, qd_len)),
            out,
            out_len,
            |i| i.n_constraints,
            |e| e.mech.gamma(e.q, e.qd, t, e.out),
        )
    }
}

/// Evaluates the mass matrix's nonzeros M(q) into `out` (`symbody_mechanism_mass_nnz`
/// entries, in `symbody_mechanism_mass_pattern` order).
///
/// # Safety
/// `m` is NULL or a live handle; `q` is NULL or points to `q_len` readable doubles; `out`
/// is NULL or points to `out_len` writable doubles not overlapping `q`.
#[no_mangle]
pub unsafe extern "C" fn symbody_mechanism_mass(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        eval(
            m,
            q,
            q_len,
            None,
            out,
            out_len,
            |i| i.mass_nnz(),
            |e| e.mech.mass(e.q, e.out),
        )
    }
}

/// Evaluates the generalized applied and velocity-dependent forces Q(q, q̇, t) into `out`
/// (`symbody_mechanism_n_coords` entries); the equations of motion are
/// `M q̈ + Φqᵀ λ = Q`, `Φq q̈ = γ`.
///
/// # Safety
/// `m` is NULL or a live handle; `q` and `qd` are NULL or point to `q_len` and `qd_len`
/// readable doubles; `out` is NULL or points to `out_len` writable doubles not overlapping
/// the inputs.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn symbody_mechanism_force(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    qd: *const f64,
    qd_len: usize,
    t: f64,
    out: *mut f64,
    out_len: usize,
) -> c_int {
    // SAFETY: the caller's contract.
    unsafe {
        eval(
            m,
            q,
            q_len,
            Some((qd, qd_len)),
            out,
            out_len,
            |i| i.n_coords,
            |e| e.mech.force(e.q, e.qd, t, e.out),
        )
    }
}

/// Evaluates the applied loads' Jacobians at `(q, q̇, t)`: ∂Q/∂q into `dq`
/// (`symbody_mechanism_force_q_nnz` entries, `symbody_mechanism_force_q_pattern` order) and
/// ∂Q/∂q̇ into `dqd` (`symbody_mechanism_force_qd_nnz` entries): the stiffness and damping of
/// the springs, dampers and actuators, for an implicit integrator's Newton matrix. With no
/// such loads both counts are 0 and the output pointers may be NULL.
///
/// # Safety
/// `m` is NULL or a live handle; `q` and `qd` are NULL or point to `q_len` and `qd_len`
/// readable doubles; `dq` and `dqd` are NULL or point to `dq_len` and `dqd_len` writable
/// doubles, neither overlapping the inputs or each other.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn symbody_mechanism_force_jacobian(
    m: *const SymbodyMechanism,
    q: *const f64,
    q_len: usize,
    qd: *const f64,
    qd_len: usize,
    t: f64,
    dq: *mut f64,
    dq_len: usize,
    dqd: *mut f64,
    dqd_len: usize,
) -> c_int {
    guard(|| {
        // SAFETY (all): the caller's contract; lengths checked inside.
        let m = unsafe { arg(m, "mechanism")? };
        let info = m.info();
        let q = unsafe { input(q, q_len, info.n_coords, "q")? };
        let qd = unsafe { input(qd, qd_len, info.n_coords, "qd")? };
        let (nq, nqd) = (info.force_q_rows.len(), info.force_qd_rows.len());
        let dq: &mut [f64] = if nq == 0 {
            &mut []
        } else {
            unsafe { output(dq, dq_len, nq, "dq")? }
        };
        let dqd: &mut [f64] = if nqd == 0 {
            &mut []
        } else {
            unsafe { output(dqd, dqd_len, nqd, "dqd")? }
        };
        m.mech.force_jacobian(q, qd, t, dq, dqd);
        Ok(())
    })
}
