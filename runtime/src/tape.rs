//! Instruction tapes: the generator's expression DAG lowered to straight-line register code
//! that a small interpreter evaluates, for mechanisms that were never compiled (decision 31,
//! as CasADi's SX virtual machine beside its C generator).
//!
//! Register layout of one tape: its constants, then the inputs `q`, `qd`, `t`, then one
//! register per instruction (instruction `k` writes register `first_result() + k`). Operands
//! always name earlier registers, so one forward sweep evaluates everything, and
//! [`Tape::new`] checks that before anything runs.

use std::cell::RefCell;

/// What one instruction computes from its operand registers `a` and `b`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    Add,
    /// `a − b`.
    Sub,
    Mul,
    Neg,
    /// `1 / a`.
    Recip,
    /// `a · a`.
    Square,
    /// `a.powi(b as i32)`: `b` holds the exponent, not a register.
    Powi,
    /// `a.atan2(b)`.
    Atan2,
    Sin,
    Cos,
    Tan,
    Exp,
    Ln,
    Sqrt,
    Abs,
    Asin,
    Acos,
    Atan,
}

impl Op {
    /// Whether `b` names a register (rather than being unused or an exponent).
    fn reads_b(self) -> bool {
        matches!(self, Op::Add | Op::Sub | Op::Mul | Op::Atan2)
    }
}

/// One instruction; its result register is implied by its position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Instr {
    pub op: Op,
    pub a: u32,
    pub b: u32,
}

/// A tape whose operands or outputs name registers that do not exist yet.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BadTape {
    pub instruction: Option<usize>,
    pub register: u32,
}

impl std::fmt::Display for BadTape {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.instruction {
            Some(k) => write!(
                f,
                "instruction {k} reads register {} before it is written",
                self.register
            ),
            None => write!(
                f,
                "an output reads register {}, which does not exist",
                self.register
            ),
        }
    }
}

impl std::error::Error for BadTape {}

/// A straight-line function of `(q, qd, t)` writing one or more output slices.
#[derive(Debug, Clone)]
pub struct Tape {
    consts: Vec<f64>,
    n_coords: usize,
    instrs: Vec<Instr>,
    /// The instructions as runs of one operation `(op, length)`: the interpreter dispatches
    /// once per run, not once per instruction (an indirect branch per instruction is
    /// mispredicted most of the time; a run is a tight loop).
    runs: Vec<(Op, u32)>,
    /// For each output slice, the register of each of its entries.
    outputs: Vec<Vec<u32>>,
}

impl Tape {
    /// Checks that every operand names an earlier register and every output an existing one.
    pub fn new(
        consts: Vec<f64>,
        n_coords: usize,
        instrs: Vec<Instr>,
        outputs: Vec<Vec<u32>>,
    ) -> Result<Self, BadTape> {
        let first = (consts.len() + 2 * n_coords + 1) as u64;
        for (k, ins) in instrs.iter().enumerate() {
            let own = first + k as u64;
            let check = |r: u32| {
                if u64::from(r) >= own {
                    Err(BadTape {
                        instruction: Some(k),
                        register: r,
                    })
                } else {
                    Ok(())
                }
            };
            check(ins.a)?;
            if ins.op.reads_b() {
                check(ins.b)?;
            }
        }
        let end = first + instrs.len() as u64;
        if let Some(&r) = outputs.iter().flatten().find(|&&r| u64::from(r) >= end) {
            return Err(BadTape {
                instruction: None,
                register: r,
            });
        }
        let mut runs: Vec<(Op, u32)> = Vec::new();
        for ins in &instrs {
            match runs.last_mut() {
                Some((op, len)) if *op == ins.op => *len += 1,
                _ => runs.push((ins.op, 1)),
            }
        }
        Ok(Tape {
            consts,
            n_coords,
            instrs,
            runs,
            outputs,
        })
    }

    /// Number of instructions (arithmetic operations and function calls).
    pub fn len(&self) -> usize {
        self.instrs.len()
    }

    pub fn is_empty(&self) -> bool {
        self.instrs.is_empty()
    }

    /// Number of runs of one operation, each dispatched once.
    pub fn runs(&self) -> usize {
        self.runs.len()
    }

    /// Number of registers an evaluation uses.
    pub fn registers(&self) -> usize {
        self.first_result() + self.instrs.len()
    }

    /// Lengths of the output slices, in order.
    pub fn output_lens(&self) -> impl Iterator<Item = usize> + '_ {
        self.outputs.iter().map(Vec::len)
    }

    fn first_result(&self) -> usize {
        self.consts.len() + 2 * self.n_coords + 1
    }

    /// Evaluates the tape at `(q, qd, t)` into `outs` (one slice per output, of the right
    /// lengths), using a register file kept per thread: no allocation once a thread has
    /// evaluated its largest tape. An empty `qd` stands for a function without velocities.
    pub fn eval(&self, q: &[f64], qd: &[f64], t: f64, outs: &mut [&mut [f64]]) {
        self.eval_joined(&[q], &[qd], t, outs);
    }

    /// [`Tape::eval`] with `q` and `qd` given in pieces, joined in order: a tape over more
    /// inputs than a mechanism's coordinates (a direction after the point) reads them
    /// without a copy. Velocities missing at the end are zero.
    pub fn eval_joined(&self, q: &[&[f64]], qd: &[&[f64]], t: f64, outs: &mut [&mut [f64]]) {
        thread_local! {
            static REGISTERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
        }
        REGISTERS.with(|cell| {
            let mut regs = cell.borrow_mut();
            if regs.len() < self.registers() {
                regs.resize(self.registers(), 0.0);
            }
            self.eval_with(&mut regs[..self.registers()], q, qd, t, outs);
        });
    }

    /// [`Tape::eval_joined`] with the caller's register file of exactly [`Tape::registers`]
    /// entries.
    pub fn eval_with(
        &self,
        regs: &mut [f64],
        q: &[&[f64]],
        qd: &[&[f64]],
        t: f64,
        outs: &mut [&mut [f64]],
    ) {
        let n = self.n_coords;
        let len = |parts: &[&[f64]]| parts.iter().map(|p| p.len()).sum::<usize>();
        assert_eq!(len(q), n, "q has the wrong length");
        assert!(len(qd) <= n, "qd has the wrong length");
        assert_eq!(
            outs.len(),
            self.outputs.len(),
            "wrong number of output slices"
        );
        let c = self.consts.len();
        regs[..c].copy_from_slice(&self.consts);
        let mut at = c;
        for part in q {
            regs[at..at + part.len()].copy_from_slice(part);
            at += part.len();
        }
        for part in qd {
            regs[at..at + part.len()].copy_from_slice(part);
            at += part.len();
        }
        regs[at..c + 2 * n].fill(0.0);
        regs[c + 2 * n] = t;
        let first = self.first_result();
        run(&self.instrs, &self.runs, regs, first);
        for (out, regs_of) in outs.iter_mut().zip(&self.outputs) {
            assert_eq!(
                out.len(),
                regs_of.len(),
                "output slice has the wrong length"
            );
            for (o, &r) in out.iter_mut().zip(regs_of) {
                *o = regs[r as usize];
            }
        }
    }
}

/// The interpreter loop: instruction `k` writes register `first + k`, one run of equal
/// operations at a time. `regs` holds at least `first + instrs.len()` registers, and
/// [`Tape::new`] checked that every operand names a register below its instruction's own.
fn run(instrs: &[Instr], runs: &[(Op, u32)], regs: &mut [f64], first: usize) {
    assert!(regs.len() >= first + instrs.len());
    let regs = regs.as_mut_ptr();
    let mut k = 0;
    for &(op, len) in runs {
        let len = len as usize;
        let chunk = &instrs[k..k + len];
        let out = first + k;
        // SAFETY (every read and write below): operands are below `first + k + j` (checked
        // by `Tape::new`) and results are below `first + instrs.len()`, so all indices lie
        // in `regs` (asserted above); reads never alias the write of the same instruction.
        macro_rules! each {
            (|$a:ident| $e:expr) => {
                for (j, ins) in chunk.iter().enumerate() {
                    unsafe {
                        let $a = *regs.add(ins.a as usize);
                        *regs.add(out + j) = $e;
                    }
                }
            };
            (|$a:ident, $b:ident| $e:expr) => {
                for (j, ins) in chunk.iter().enumerate() {
                    unsafe {
                        let ($a, $b) = (*regs.add(ins.a as usize), *regs.add(ins.b as usize));
                        *regs.add(out + j) = $e;
                    }
                }
            };
        }
        match op {
            Op::Add => each!(|a, b| a + b),
            Op::Sub => each!(|a, b| a - b),
            Op::Mul => each!(|a, b| a * b),
            Op::Atan2 => each!(|a, b| a.atan2(b)),
            Op::Neg => each!(|a| -a),
            Op::Recip => each!(|a| 1.0 / a),
            Op::Square => each!(|a| a * a),
            // `b` holds the exponent, not a register: read `a` only.
            Op::Powi => {
                for (j, ins) in chunk.iter().enumerate() {
                    unsafe {
                        let a = *regs.add(ins.a as usize);
                        *regs.add(out + j) = a.powi(ins.b as i32);
                    }
                }
            }
            Op::Sin => each!(|a| crate::trig::sin(a)),
            Op::Cos => each!(|a| crate::trig::cos(a)),
            Op::Tan => each!(|a| a.tan()),
            Op::Exp => each!(|a| a.exp()),
            Op::Ln => each!(|a| a.ln()),
            Op::Sqrt => each!(|a| a.sqrt()),
            Op::Abs => each!(|a| a.abs()),
            Op::Asin => each!(|a| a.asin()),
            Op::Acos => each!(|a| a.acos()),
            Op::Atan => each!(|a| a.atan()),
        }
        k += len;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evaluates_in_register_order_and_rejects_forward_reads() {
        // consts [2.0], q = [x], qd = [v], t: registers 0, 1, 2, 3; results from 4.
        let instrs = vec![
            Instr {
                op: Op::Mul,
                a: 0,
                b: 1,
            }, // 4: 2x
            Instr {
                op: Op::Sin,
                a: 4,
                b: 0,
            }, // 5: sin 2x
            Instr {
                op: Op::Sub,
                a: 5,
                b: 3,
            }, // 6: sin 2x − t
            Instr {
                op: Op::Powi,
                a: 2,
                b: 3,
            }, // 7: v³
        ];
        let tape = Tape::new(vec![2.0], 1, instrs, vec![vec![6, 7], vec![0]]).unwrap();
        let (mut a, mut b) = ([0.0; 2], [0.0; 1]);
        tape.eval(&[0.3], &[2.0], 0.5, &mut [&mut a, &mut b]);
        assert_eq!(a, [crate::trig::sin(0.6) - 0.5, 8.0]);
        assert_eq!(b, [2.0]);
        let bad = Tape::new(
            vec![],
            1,
            vec![Instr {
                op: Op::Neg,
                a: 3,
                b: 0,
            }],
            vec![],
        );
        assert_eq!(
            bad.unwrap_err(),
            BadTape {
                instruction: Some(0),
                register: 3
            }
        );
        let bad = Tape::new(vec![], 1, vec![], vec![vec![3]]);
        assert_eq!(
            bad.unwrap_err(),
            BadTape {
                instruction: None,
                register: 3
            }
        );
    }
}
