//! Helpers shared by the command's tests.
#![allow(dead_code)]

pub mod cli;
