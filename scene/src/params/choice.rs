//! The `choice!` macro that declares the view's choices among words (`view.rs`).

/// Declares a choice among words: the enum, its words in order, and the conversions.
macro_rules! choice {
    ($(#[$doc:meta])* $name:ident { $($(#[$vdoc:meta])* $variant:ident = $word:literal),+ $(,)? }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub enum $name {
            #[default]
            $($(#[$vdoc])* $variant),+
        }

        impl $name {
            /// The words a link or attribute uses, in order.
            pub const WORDS: &'static [&'static str] = &[$($word),+];

            /// Every choice, in the order of `WORDS`.
            pub const ALL: &'static [Self] = &[$(Self::$variant),+];

            /// The word for this choice.
            pub fn word(self) -> &'static str {
                match self { $(Self::$variant => $word),+ }
            }

            /// The choice a word names.
            pub fn from_word(word: &str) -> Option<Self> {
                match word { $($word => Some(Self::$variant),)+ _ => None }
            }

            /// Its position in `WORDS`, as the shaders number it.
            pub fn index(self) -> u32 {
                self as u32
            }
        }
    };
}
pub(crate) use choice;
