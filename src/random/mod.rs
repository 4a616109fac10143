//! Random baselines: the samplers the low-discrepancy constructions are measured against,
//! each random access (a coordinate is a hash of `(seed, index, dimension)`).
//!
//! | module | sampler | error of a smooth integral |
//! |---|---|---|
//! | [`independent`] | [`Independent`](crate::Independent): independent uniform points (plain Monte Carlo) | `O(N^-1/2)` |
//! | [`stratified`] | [`Stratified`](crate::Stratified): one point a cell of a grid, jittered ([`Jitter`](crate::Jitter)) or centred | `O(N^(-1/2 - 1/d))` |
//! | [`cmj`] | [`CorrelatedMultiJitter`](cmj::CorrelatedMultiJitter): Kensler's correlated multi-jittered 2D patterns, stratified in the `m x n` cells and the N-rooks grid (pairs of dimensions) | `O(N^-1)` for smooth 2D integrands, as jittered |
//! | [`latin_hypercube`] | [`LatinHypercube`](crate::LatinHypercube): one point in each of the `N` slabs of every axis | `O(N^-1/2)`, less for additive integrands |

pub mod cmj;
pub mod independent;
pub mod latin_hypercube;
pub mod stratified;
