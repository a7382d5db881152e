//! Step 1: tokens to [`RawInput`] (`#[attr]* key = value, key = value, ...`), no interpretation.

use crate::model::{RawEntry, RawInput};
use proc_macro2::{TokenStream, TokenTree};
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::{Attribute, Ident, Token};

impl Parse for RawInput {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let attrs = input.call(Attribute::parse_outer)?;
        let mut entries = Vec::new();
        while !input.is_empty() {
            if !input.peek(Ident::peek_any) {
                return Err(input.error(
                    "expected a key: one of `vis`, `name`, `shape`, `degree` (as in `degree = 3`)",
                ));
            }
            let key = input.call(Ident::parse_any)?;
            if !input.peek(Token![=]) {
                return Err(input.error(format!("expected `=` after the key `{key}`")));
            }
            let eq: Token![=] = input.parse()?;
            let mut value = TokenStream::new();
            while !input.is_empty() && !input.peek(Token![,]) {
                value.extend([input.parse::<TokenTree>()?]);
            }
            entries.push(RawEntry { key, eq, value });
            if !input.is_empty() {
                input.parse::<Token![,]>()?;
            }
        }
        Ok(RawInput { attrs, entries })
    }
}

/// Parses the macro input into its raw entries.
pub fn parse(input: TokenStream) -> syn::Result<RawInput> {
    syn::parse2(input)
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    #[test]
    fn entries_split_at_top_level_commas() {
        let raw = parse(quote!(#[inline] vis = pub(crate), name = f, degree = (3, 2),)).unwrap();
        assert_eq!(raw.attrs.len(), 1);
        let keys: Vec<String> = raw.entries.iter().map(|e| e.key.to_string()).collect();
        assert_eq!(keys, ["vis", "name", "degree"]);
        assert_eq!(raw.entries[2].value.to_string(), "(3 , 2)");
    }

    #[test]
    fn a_key_without_equals_is_an_error() {
        let e = parse(quote!(name f)).err().unwrap();
        assert_eq!(e.to_string(), "expected `=` after the key `name`");
    }
}
