//! Identity stand-ins for Kani's harness attributes, for a type check only.
use proc_macro::TokenStream;

/// `#[kani::proof]`.
#[proc_macro_attribute]
pub fn proof(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}

/// `#[kani::unwind(n)]`.
#[proc_macro_attribute]
pub fn unwind(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}

/// `#[kani::solver(s)]`.
#[proc_macro_attribute]
pub fn solver(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}
