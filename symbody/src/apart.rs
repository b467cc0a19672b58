//! Keeps a run's two threads on two CPUs: a thread spawned beside a busy one may start on
//! the busy one's CPU, and Linux then leaves the two sharing it.
//!
//! Measured on the project's 2-core VM (2026-11-29, the paper scene): the recording thread
//! started on the path's CPU in 5 of 12 runs and was still there after 5 ms of yielding (no
//! load balancing moved it to the idle CPU); those runs printed 12.7–14.0 ms, the others
//! 7.3–9.2 ms. A thread that finds itself on its partner's CPU moves itself to the others
//! the process may use, then lets itself run anywhere again (the move wakes the idle CPU,
//! so the thread waits for it instead of taking turns with its partner).

/// The CPU the calling thread runs on, where the platform tells.
pub(crate) fn current() -> Option<usize> {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: no arguments; returns -1 on failure.
        let cpu = unsafe { libc::sched_getcpu() };
        usize::try_from(cpu).ok()
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}

/// Moves the calling thread off `partner`'s CPU when it runs there (and may use another),
/// then allows it every CPU it had; the CPU it moved to, if it moved. Does nothing where the
/// platform does not tell CPUs apart.
pub(crate) fn leave(partner: Option<usize>) -> Option<usize> {
    #[cfg(target_os = "linux")]
    {
        let busy = partner?;
        if current() != Some(busy) {
            return None;
        }
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: `cpu_set_t` is plain data (zeroed is the empty set); the calls read and
        // write only the sets given, of the size given, for the calling thread (pid 0).
        unsafe {
            let mut allowed: libc::cpu_set_t = std::mem::zeroed();
            if libc::sched_getaffinity(0, size, &mut allowed) != 0 {
                return None;
            }
            let mut others: libc::cpu_set_t = std::mem::zeroed();
            for cpu in (0..libc::CPU_SETSIZE as usize).filter(|&c| c != busy) {
                if libc::CPU_ISSET(cpu, &allowed) {
                    libc::CPU_SET(cpu, &mut others);
                }
            }
            if libc::CPU_COUNT(&others) == 0 {
                return None;
            }
            // Returns once the thread runs on one of `others`.
            if libc::sched_setaffinity(0, size, &others) != 0 {
                return None;
            }
            let moved = current();
            libc::sched_setaffinity(0, size, &allowed);
            moved
        }
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = partner;
        None
    }
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    fn allowed() -> Vec<usize> {
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: reads the calling thread's set into a zeroed one of the size given.
        unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            assert_eq!(libc::sched_getaffinity(0, size, &mut set), 0);
            (0..libc::CPU_SETSIZE as usize)
                .filter(|&c| libc::CPU_ISSET(c, &set))
                .collect()
        }
    }

    fn pin(cpu: usize) {
        allow(&[cpu]);
    }

    fn allow(cpus: &[usize]) {
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: sets the calling thread's set to CPUs it may use.
        unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            for &c in cpus {
                libc::CPU_SET(c, &mut set);
            }
            assert_eq!(libc::sched_setaffinity(0, size, &set), 0);
        }
    }

    /// On a thread of its own (the pinning is the thread's): a thread on its partner's CPU
    /// moves to another it may use, and may use every CPU it had again afterwards.
    #[test]
    fn a_thread_leaves_its_partners_cpu_and_keeps_its_cpus() {
        std::thread::spawn(|| {
            let all = allowed();
            let [first, ..] = all[..] else {
                return;
            };
            // Onto `first`, then allowed everywhere again: it runs there until moved (or
            // until Linux moves it first, which a few tries rule out).
            let moves: Vec<Option<usize>> = (0..10)
                .map(|_| {
                    pin(first);
                    allow(&all);
                    let moved = leave(Some(first));
                    assert_eq!(allowed(), all);
                    moved
                })
                .collect();
            if all.len() == 1 {
                assert!(
                    moves.iter().all(Option::is_none),
                    "nowhere to go: {moves:?}"
                );
            } else {
                assert!(moves
                    .iter()
                    .flatten()
                    .all(|c| *c != first && all.contains(c)));
                assert!(moves.iter().any(Option::is_some), "{moves:?}");
            }
        })
        .join()
        .unwrap();
    }
}
