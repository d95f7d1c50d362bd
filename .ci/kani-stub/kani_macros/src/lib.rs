//! Stand-ins for Kani's attributes, for a type check only: the harness
//! attributes leave their item as it is; the contract attributes also emit
//! code that type-checks what they name (the condition of `requires`, the
//! closure of `ensures` applied to the function's result, the path of
//! `proof_for_contract` and `stub_verified`), so that a contract that would
//! not compile under Kani fails here too.
use proc_macro::{Delimiter, Group, Ident, Punct, Spacing, Span, TokenStream, TokenTree};

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

/// `#[kani::proof_for_contract(path)]`: the path must name a function.
#[proc_macro_attribute]
pub fn proof_for_contract(attr: TokenStream, item: TokenStream) -> TokenStream {
    with_path_check(attr, item)
}

/// `#[kani::stub_verified(path)]`: the path must name a function.
#[proc_macro_attribute]
pub fn stub_verified(attr: TokenStream, item: TokenStream) -> TokenStream {
    with_path_check(attr, item)
}

/// `#[kani::requires(cond)]`: `cond` must be a `bool` over the parameters.
#[proc_macro_attribute]
pub fn requires(attr: TokenStream, item: TokenStream) -> TokenStream {
    let body: TokenStream = format!("{{ let _: bool = {attr}; }}").parse().expect("a block");
    with_sibling(item, "__kani_requires_", body, false)
}

/// `#[kani::ensures(closure)]`: the closure must take a reference to the
/// result and return a `bool`.
#[proc_macro_attribute]
pub fn ensures(attr: TokenStream, item: TokenStream) -> TokenStream {
    let body: TokenStream =
        format!("{{ let __result: __Ret = loop {{}}; let _: bool = ({attr})(&__result); }}").parse().expect("a block");
    with_sibling(item, "__kani_ensures_", body, true)
}

fn with_path_check(attr: TokenStream, item: TokenStream) -> TokenStream {
    let check: TokenStream = format!("const _: () = {{ let _ = {attr}; }};").parse().expect("an item");
    let mut out = item;
    out.extend(check);
    out
}

/// The item, then a function with the item's parameters (and, for
/// `ensures`, its return type as `__Ret`) whose body is `body`.
fn with_sibling(item: TokenStream, prefix: &str, body: TokenStream, with_ret: bool) -> TokenStream {
    let tokens: Vec<TokenTree> = item.clone().into_iter().collect();
    let at_fn = tokens
        .iter()
        .position(|t| matches!(t, TokenTree::Ident(i) if i.to_string() == "fn"))
        .expect("a contract on a function");
    let TokenTree::Ident(name) = &tokens[at_fn + 1] else { panic!("a function name") };
    let TokenTree::Group(params) = &tokens[at_fn + 2] else { panic!("a parameter list") };
    // The return type: the tokens between `->` and the body (no where clauses here).
    let body_at = tokens.len() - 1;
    let ret: Vec<TokenTree> = if matches!(&tokens[at_fn + 3], TokenTree::Punct(p) if p.as_char() == '-') {
        tokens[at_fn + 5..body_at].to_vec()
    } else {
        "()".parse::<TokenStream>().expect("unit").into_iter().collect()
    };
    let mut sibling: TokenStream =
        "#[allow(dead_code, unused_variables, unreachable_code, non_snake_case, clippy::all)]".parse().expect("attr");
    sibling.extend([
        TokenTree::Ident(Ident::new("fn", Span::call_site())),
        TokenTree::Ident(Ident::new(&format!("{prefix}{name}"), name.span())),
        TokenTree::Group(params.clone()),
    ]);
    let mut inner = TokenStream::new();
    if with_ret {
        inner.extend("type __Ret =".parse::<TokenStream>().expect("type"));
        inner.extend(ret);
        inner.extend([TokenTree::Punct(Punct::new(';', Spacing::Alone))]);
    }
    inner.extend(body);
    sibling.extend([TokenTree::Group(Group::new(Delimiter::Brace, inner))]);
    let mut out = item;
    out.extend(sibling);
    out
}
