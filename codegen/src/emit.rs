//! Lowering of DAG outputs to straight-line Rust: outputs are grouped into chunks of a few
//! hundred statements, each an `#[inline(never)]` function (docs/design.md, decision 5); nodes
//! needed by more than one chunk are computed once into a stack array shared by all chunks.

use crate::expr::{Arena, Func, Id, Node, Var};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::collections::HashMap;

/// Statements per chunk function: large enough that few values cross chunks through the
/// shared array, small enough that rustc compiles each function quickly. Measured on the
/// Stewart model (callgrind, criterion): 600 cuts γ by ≈ 20 % in instructions and time
/// against 300; 1 000–2 000 cut instructions further but made `eval_kinematics` slower in
/// time (larger frames), and rustc was seen crashing near 3 000 (docs/design.md, decision 5).
pub const CHUNK_STATEMENTS: usize = 600;

/// An input of the generated function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    Q,
    Qd,
    T,
    /// The run-time parameters `p` (`Var::P`).
    P,
    /// The values `setup` computed from them, `k` (`Var::K`).
    K,
    /// The direction of a directional derivative: `dq`, `dqd`, `dp` (`Var::Dq`, …).
    Dq,
    Dqd,
    Dp,
}

impl Input {
    /// Every input, in the order of generated signatures.
    const ALL: [Input; 8] = [
        Input::P,
        Input::K,
        Input::Q,
        Input::Qd,
        Input::T,
        Input::Dq,
        Input::Dqd,
        Input::Dp,
    ];

    fn name(self) -> &'static str {
        match self {
            Input::Q => "q",
            Input::Qd => "qd",
            Input::T => "t",
            Input::P => "p",
            Input::K => "k",
            Input::Dq => "dq",
            Input::Dqd => "dqd",
            Input::Dp => "dp",
        }
    }

    fn reads(self, v: Var) -> bool {
        matches!(
            (v, self),
            (Var::Q(_), Input::Q)
                | (Var::Qd(_), Input::Qd)
                | (Var::T, Input::T)
                | (Var::P(_), Input::P)
                | (Var::K(_), Input::K)
                | (Var::Dq(_), Input::Dq)
                | (Var::Dqd(_), Input::Dqd)
                | (Var::Dp(_), Input::Dp)
        )
    }
}

/// One output slice of a generated function.
pub struct Output<'a> {
    /// Parameter name, e.g. `phi_q`.
    pub name: &'a str,
    pub values: &'a [Id],
    /// The constraint row of each value, when the output is row-indexed. A fused function
    /// chunks its row-indexed outputs row by row (Φ, Φq, Φt, γ of one joint together), so
    /// the subexpressions of one joint stay inside one chunk instead of crossing chunks.
    pub rows: Option<&'a [u32]>,
}

impl<'a> Output<'a> {
    /// An output chunked in its own order.
    pub fn new(name: &'a str, values: &'a [Id]) -> Self {
        Output {
            name,
            values,
            rows: None,
        }
    }

    /// An output whose values belong to constraint rows `rows`.
    pub fn by_rows(name: &'a str, values: &'a [Id], rows: &'a [u32]) -> Self {
        Output {
            name,
            values,
            rows: Some(rows),
        }
    }
}

/// A function to emit.
pub struct Function<'a> {
    pub name: &'a str,
    pub doc: &'a str,
    /// Inputs of the public signature, in order.
    pub inputs: &'a [Input],
    pub outputs: Vec<Output<'a>>,
    /// Length of `q` and `qd`.
    pub n_coords: usize,
    /// Length of `p` and of `k` (0 where there are none).
    pub n_p: usize,
    pub n_k: usize,
}

impl Function<'_> {
    fn len(&self, input: Input) -> usize {
        match input {
            Input::Q | Input::Qd | Input::T | Input::Dq | Input::Dqd => self.n_coords,
            Input::P | Input::Dp => self.n_p,
            Input::K => self.n_k,
        }
    }
}

fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}

/// An unsuffixed integer literal (`quote!` would write `3usize`).
fn int(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

fn node_ident(id: Id) -> Ident {
    ident(&format!("x{}", id.0))
}

/// Where a node's value lives while a chunk runs.
#[derive(Clone, Copy, PartialEq)]
enum Place {
    /// Not needed.
    None,
    /// A `let` in the chunk being emitted.
    Local,
    /// `s[k]` of the shared array.
    Shared(usize),
}

struct Lowering<'a> {
    arena: &'a Arena,
    /// Which chunk last claimed each node, and how many chunks use it.
    last_chunk: Vec<usize>,
    users: Vec<u32>,
    stamp: Vec<u32>,
    epoch: u32,
}

impl<'a> Lowering<'a> {
    fn new(arena: &'a Arena) -> Self {
        let n = arena.len();
        Lowering {
            arena,
            last_chunk: vec![usize::MAX; n],
            users: vec![0; n],
            stamp: vec![0; n],
            epoch: 0,
        }
    }

    /// The non-leaf nodes in the cone of `root`, ascending.
    fn cone(&mut self, root: Id) -> Vec<u32> {
        self.epoch += 1;
        let mut out = Vec::new();
        let mut stack = vec![root];
        while let Some(id) = stack.pop() {
            let i = id.index();
            if self.stamp[i] == self.epoch {
                continue;
            }
            self.stamp[i] = self.epoch;
            let node = self.arena.node(id);
            if matches!(node, Node::Const(_) | Node::Var(_)) {
                continue;
            }
            out.push(id.0);
            stack.extend(operands(self.arena, id));
        }
        out.sort_unstable();
        out
    }
}

fn leaf_tokens(arena: &Arena, id: Id, receiver: bool) -> Option<TokenStream> {
    match arena.node(id) {
        Node::Const(bits) => {
            let v = f64::from_bits(bits);
            let lit = if receiver {
                Literal::f64_suffixed(v.abs())
            } else {
                Literal::f64_unsuffixed(v.abs())
            };
            // A negative receiver needs parentheses: `-1.0f64.sin()` is `-(1.0f64.sin())`.
            Some(match (v < 0.0, receiver) {
                (true, true) => quote!((-#lit)),
                (true, false) => quote!(-#lit),
                (false, _) => quote!(#lit),
            })
        }
        Node::Var(Var::Q(i)) => {
            let i = int(i as usize);
            Some(quote!(q[#i]))
        }
        Node::Var(Var::Qd(i)) => {
            let i = int(i as usize);
            Some(quote!(qd[#i]))
        }
        Node::Var(Var::T) => Some(quote!(t)),
        Node::Var(Var::P(i)) => {
            let i = int(i as usize);
            Some(quote!(p[#i]))
        }
        Node::Var(Var::K(i)) => {
            let i = int(i as usize);
            Some(quote!(k[#i]))
        }
        Node::Var(Var::Dq(i)) => {
            let i = int(i as usize);
            Some(quote!(dq[#i]))
        }
        Node::Var(Var::Dqd(i)) => {
            let i = int(i as usize);
            Some(quote!(dqd[#i]))
        }
        Node::Var(Var::Dp(i)) => {
            let i = int(i as usize);
            Some(quote!(dp[#i]))
        }
        _ => None,
    }
}

/// The nodes an emitted statement reads: like `Node::children`, except that `a + (−y)` is
/// emitted as `a - y` and so reads `y`, not the negation.
fn operands(arena: &Arena, id: Id) -> Vec<Id> {
    let node = arena.node(id);
    if let Node::Add(a, b) = node {
        if let Node::Neg(y) = arena.node(b) {
            return vec![a, y];
        }
        if let Node::Neg(x) = arena.node(a) {
            return vec![b, x];
        }
    }
    node.children().collect()
}

/// Tokens that read node `id` inside a chunk, given where each node lives.
fn reference(arena: &Arena, places: &[Place], id: Id, receiver: bool) -> TokenStream {
    if let Some(t) = leaf_tokens(arena, id, receiver) {
        return t;
    }
    match places[id.index()] {
        Place::Shared(k) => {
            let k = int(k);
            quote!(s[#k])
        }
        _ => {
            let x = node_ident(id);
            quote!(#x)
        }
    }
}

fn expression(arena: &Arena, places: &[Place], id: Id) -> TokenStream {
    let r = |x: Id| reference(arena, places, x, false);
    let recv = |x: Id| reference(arena, places, x, true);
    match arena.node(id) {
        Node::Add(a, b) => {
            let neg_of = |x: Id| match arena.node(x) {
                Node::Neg(y) => Some(y),
                _ => None,
            };
            let neg_const = |x: Id| arena.as_const(x).filter(|c| *c < 0.0);
            if let Some(y) = neg_of(b) {
                let (a, y) = (r(a), r(y));
                quote!(#a - #y)
            } else if let Some(x) = neg_of(a) {
                let (b, x) = (r(b), r(x));
                quote!(#b - #x)
            } else if let Some(c) = neg_const(b) {
                let (a, c) = (r(a), Literal::f64_unsuffixed(-c));
                quote!(#a - #c)
            } else if let Some(c) = neg_const(a) {
                let (b, c) = (r(b), Literal::f64_unsuffixed(-c));
                quote!(#b - #c)
            } else {
                let (a, b) = (r(a), r(b));
                quote!(#a + #b)
            }
        }
        Node::Mul(a, b) => {
            let (a, b) = (r(a), r(b));
            quote!(#a * #b)
        }
        Node::Neg(a) => {
            let a = r(a);
            quote!(-#a)
        }
        Node::Recip(a) => {
            let a = r(a);
            quote!(1.0 / #a)
        }
        Node::Powi(a, 2) => {
            let a = r(a);
            quote!(#a * #a)
        }
        Node::Powi(a, n) => {
            let a = recv(a);
            quote!(#a.powi(#n))
        }
        Node::Atan2(y, x) => {
            let (y, x) = (recv(y), r(x));
            quote!(#y.atan2(#x))
        }
        // One sine and cosine everywhere (the runtime's `trig`): generated code, the
        // interpreter and constant folding agree to the last bit.
        Node::Call(Func::Sin, a) => {
            let a = r(a);
            quote!(symbody_runtime::trig::sin(#a))
        }
        Node::Call(Func::Cos, a) => {
            let a = r(a);
            quote!(symbody_runtime::trig::cos(#a))
        }
        Node::Call(f, a) => {
            let a = recv(a);
            let m = ident(f.name());
            quote!(#a.#m())
        }
        Node::Const(_) | Node::Var(_) => unreachable!("leaves are inlined"),
    }
}

/// The `let` statements computing `nodes` (in order), each passed through `wrap` with the
/// nodes it defines. A sine and a cosine of the same argument that are both among `nodes`
/// become one `sin_cos` (one argument reduction) where the first of them stood.
fn statements(
    arena: &Arena,
    places: &[Place],
    nodes: &[u32],
    wrap: impl Fn(&[u32], TokenStream) -> TokenStream,
) -> Vec<TokenStream> {
    let mut pairs: HashMap<Id, [Option<u32>; 2]> = HashMap::new();
    for &m in nodes {
        match arena.node(Id(m)) {
            Node::Call(Func::Sin, a) => pairs.entry(a).or_default()[0] = Some(m),
            Node::Call(Func::Cos, a) => pairs.entry(a).or_default()[1] = Some(m),
            _ => {}
        }
    }
    let mut out = Vec::with_capacity(nodes.len());
    for &m in nodes {
        let pair = match arena.node(Id(m)) {
            Node::Call(Func::Sin | Func::Cos, a) => match pairs[&a] {
                [Some(sin), Some(cos)] => Some((a, sin, cos)),
                _ => None,
            },
            _ => None,
        };
        match pair {
            Some((a, sin, cos)) if m == sin.min(cos) => {
                let (xs, xc) = (node_ident(Id(sin)), node_ident(Id(cos)));
                let a = reference(arena, places, a, false);
                let stmt = quote!(let (#xs, #xc) = symbody_runtime::trig::sin_cos(#a););
                out.push(wrap(&[sin, cos], stmt));
            }
            Some(_) => {}
            None => {
                let x = node_ident(Id(m));
                let e = expression(arena, places, Id(m));
                out.push(wrap(&[m], quote!(let #x = #e;)));
            }
        }
    }
    out
}

fn uses_input(arena: &Arena, nodes: &[u32], direct: &[Id], input: Input) -> bool {
    let is = |id: Id| matches!(arena.node(id), Node::Var(v) if input.reads(v));
    nodes
        .iter()
        .flat_map(|&n| operands(arena, Id(n)))
        .chain(direct.iter().copied())
        .any(is)
}

fn input_param(input: Input, n: usize, used: bool, array: bool) -> TokenStream {
    let name = match used {
        true => ident(input.name()),
        false => ident(&format!("_{}", input.name())),
    };
    let n = int(n);
    match (input, array) {
        (Input::T, _) => quote!(#name: f64),
        (_, true) => quote!(#name: &[f64; #n]),
        (_, false) => quote!(#name: &[f64]),
    }
}

/// Emits the public function and its chunk helpers.
pub fn function(arena: &Arena, f: &Function<'_>) -> TokenStream {
    let mut low = Lowering::new(arena);
    // Flatten outputs into (output index, slot, value).
    let mut slots: Vec<(usize, usize, Id)> = f
        .outputs
        .iter()
        .enumerate()
        .flat_map(|(o, out)| out.values.iter().enumerate().map(move |(k, &v)| (o, k, v)))
        .collect();
    // Row-indexed outputs row by row, then the others in their own order (stable sort).
    let row_key = |&(o, k, _): &(usize, usize, Id)| f.outputs[o].rows.map_or(u32::MAX, |r| r[k]);
    slots.sort_by_key(row_key);

    // Greedy chunking in output order.
    let mut chunk_of_slot = Vec::with_capacity(slots.len());
    let mut chunk = 0usize;
    let mut size = 0usize;
    let mut cones = Vec::with_capacity(slots.len());
    for &(_, _, v) in &slots {
        let cone = low.cone(v);
        let new = cone
            .iter()
            .filter(|&&n| low.last_chunk[n as usize] != chunk)
            .count();
        if size > 0 && size + new > CHUNK_STATEMENTS {
            chunk += 1;
            size = 0;
        }
        for &n in &cone {
            let n = n as usize;
            if low.last_chunk[n] != chunk {
                low.last_chunk[n] = chunk;
                low.users[n] += 1;
                size += 1;
            }
        }
        chunk_of_slot.push(chunk);
        cones.push(cone);
    }
    let n_chunks = if slots.is_empty() { 0 } else { chunk + 1 };

    // Nodes used by two or more chunks are computed once, into `s`.
    let shared: Vec<u32> = (0..arena.len() as u32)
        .filter(|&n| low.users[n as usize] >= 2)
        .collect();
    let mut places = vec![Place::None; arena.len()];
    for (k, &n) in shared.iter().enumerate() {
        places[n as usize] = Place::Shared(k);
    }
    let ns = int(shared.len());

    let mut helpers = Vec::new();
    let mut calls = Vec::new();
    let name = f.name;

    // Shared prologue, itself chunked; within a group, values are also kept as locals.
    for (g, group) in shared.chunks(CHUNK_STATEMENTS).enumerate() {
        let fname = ident(&format!("{name}_shared_{g}"));
        let mut local_places = places.clone();
        for &m in group {
            local_places[m as usize] = Place::Local;
        }
        let store = |m: u32| {
            let Place::Shared(k) = places[m as usize] else {
                unreachable!()
            };
            let (x, k) = (node_ident(Id(m)), int(k));
            quote!(s[#k] = #x;)
        };
        let stmts = statements(arena, &local_places, group, |m, stmt| {
            let stores = m.iter().map(|&m| store(m));
            quote!(#stmt #(#stores)*)
        });
        let used: Vec<bool> = Input::ALL
            .iter()
            .map(|&inp| uses_input(arena, group, &[], inp))
            .collect();
        let params: Vec<TokenStream> = Input::ALL
            .iter()
            .zip(&used)
            .filter(|(inp, _)| f.inputs.contains(inp))
            .map(|(&inp, &u)| input_param(inp, f.len(inp), u, true))
            .collect();
        let args: Vec<TokenStream> = Input::ALL
            .iter()
            .filter(|inp| f.inputs.contains(inp))
            .map(|inp| {
                let name = ident(inp.name());
                quote!(#name)
            })
            .collect();
        helpers.push(quote! {
            #[inline(never)]
            fn #fname(#(#params,)* s: &mut [f64; #ns]) {
                #(#stmts)*
            }
        });
        calls.push(quote!(#fname(#(#args,)* &mut s);));
    }

    // Output chunks.
    for c in 0..n_chunks {
        let members: Vec<usize> = (0..slots.len())
            .filter(|&i| chunk_of_slot[i] == c)
            .collect();
        let mut locals: Vec<u32> = members
            .iter()
            .flat_map(|&i| cones[i].iter().copied())
            .filter(|&m| places[m as usize] == Place::None)
            .collect();
        locals.sort_unstable();
        locals.dedup();
        let mut local_places = places.clone();
        for &m in &locals {
            local_places[m as usize] = Place::Local;
        }
        let stmts = statements(arena, &local_places, &locals, |_, stmt| stmt);
        let writes: Vec<TokenStream> = members
            .iter()
            .map(|&i| {
                let (o, k, v) = slots[i];
                let k = int(k);
                let out = ident(f.outputs[o].name);
                let val = reference(arena, &local_places, v, false);
                quote!(#out[#k] = #val;)
            })
            .collect();
        let direct: Vec<Id> = members.iter().map(|&i| slots[i].2).collect();
        let uses_shared = locals
            .iter()
            .flat_map(|&m| operands(arena, Id(m)))
            .chain(direct.iter().copied())
            .any(|x| matches!(places[x.index()], Place::Shared(_)));
        let outs_used: Vec<usize> = {
            let mut o: Vec<usize> = members.iter().map(|&i| slots[i].0).collect();
            o.sort_unstable();
            o.dedup();
            o
        };
        let fname = ident(&format!("{name}_part_{c}"));
        let mut params: Vec<TokenStream> = Vec::new();
        let mut args: Vec<TokenStream> = Vec::new();
        for inp in Input::ALL {
            if f.inputs.contains(&inp) && uses_input(arena, &locals, &direct, inp) {
                params.push(input_param(inp, f.len(inp), true, true));
                let name = ident(inp.name());
                args.push(quote!(#name));
            }
        }
        if uses_shared {
            params.push(quote!(s: &[f64; #ns]));
            args.push(quote!(&s));
        }
        for &o in &outs_used {
            let out = ident(f.outputs[o].name);
            let len = int(f.outputs[o].values.len());
            params.push(quote!(#out: &mut [f64; #len]));
            args.push(quote!(#out));
        }
        helpers.push(quote! {
            #[inline(never)]
            fn #fname(#(#params),*) {
                #(#stmts)*
                #(#writes)*
            }
        });
        calls.push(quote!(#fname(#(#args),*);));
    }

    // Public entry point: slices in, fixed-size arrays inside.
    let pub_name = ident(name);
    let doc = f.doc;
    let mut params = Vec::new();
    let mut conversions = Vec::new();
    for &inp in Input::ALL.iter().filter(|inp| f.inputs.contains(inp)) {
        params.push(input_param(inp, f.len(inp), true, false));
        let (name, len) = (ident(inp.name()), int(f.len(inp)));
        let msg = match inp {
            Input::Q | Input::Qd | Input::Dq | Input::Dqd => {
                format!("{} must have n_coords entries", inp.name())
            }
            _ => format!("{} must have {} entries", inp.name(), f.len(inp)),
        };
        if inp != Input::T {
            conversions.push(quote! {
                let #name: &[f64; #len] = #name.try_into().expect(#msg);
            });
        }
    }
    for out in &f.outputs {
        let o = ident(out.name);
        let msg = format!("{} must have {} entries", out.name, out.values.len());
        let len = int(out.values.len());
        params.push(quote!(#o: &mut [f64]));
        // An empty output (no load Jacobian) is still checked, then has nothing to write.
        let binding = if out.values.is_empty() {
            quote!(_)
        } else {
            quote!(#o)
        };
        conversions.push(quote! {
            let #binding: &mut [f64; #len] = #o.try_into().expect(#msg);
        });
    }
    // Inputs no chunk reads are still part of the contract; mark them used.
    let all_nodes: Vec<u32> = cones.iter().flatten().copied().collect();
    let all_direct: Vec<Id> = slots.iter().map(|s| s.2).collect();
    let touch: Vec<TokenStream> = f
        .inputs
        .iter()
        .filter(|&&inp| !uses_input(arena, &all_nodes, &all_direct, inp))
        .map(|inp| {
            let name = ident(inp.name());
            quote!(let _ = #name;)
        })
        .collect();
    let shared_decl = if !shared.is_empty() {
        quote!(let mut s = [0.0f64; #ns];)
    } else {
        quote!()
    };
    quote! {
        #[doc = #doc]
        pub fn #pub_name(#(#params),*) {
            #(#conversions)*
            #(#touch)*
            #shared_decl
            #(#calls)*
        }
        #(#helpers)*
    }
}
