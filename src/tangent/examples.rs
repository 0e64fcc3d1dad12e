//! Paper 004's examples, recomputed exactly (filled in below).
use crate::examples::ExampleResult;

/// The examples of paper 004 side by side with what the paper printed.
pub fn paper_examples() -> Vec<ExampleResult> {
    Vec::new()
}
