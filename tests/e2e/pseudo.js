// Pseudo-languages, for tests only: an accented English about 40 % longer (`en-XA`), and a right-to-left
// one (`ar-XB`, written right to left as Arabic is), made from the English catalogue key by key. They
// show where a longer or a mirrored language would clip, overflow or run the wrong way, without a
// translator. Placeholders and plural forms are kept.

const ACCENTED = Object.fromEntries([...'aeiouAEIOUcnyCNY'].map((c, i) => [c, 'åéîøüÅÉÎØÜçñýÇÑÝ'[i]]));

// Each run of text between placeholders changed by `f`.
const keepingFields = (text, f) => text.split(/(\{[a-zA-Z0-9_]+\})/).map((part, i) => (i % 2 ? part : f(part))).join('');

function longer(text) {
  const accented = keepingFields(text, (part) => [...part].map((c) => ACCENTED[c] ?? c).join(''));
  const letters = text.replace(/\{[^}]*\}/g, '').length;
  return `${accented}${letters ? ` ${'·'.repeat(Math.ceil(letters * 0.4))}` : ''}`;
}

// Each word in Hebrew letters (a right-to-left script), numbers and placeholders kept.
const HEBREW = 'אבגדהוזחטיכלמנסעפצקרשת';
const rightToLeft = (text) => keepingFields(text, (part) => part.replace(/[A-Za-z]/g,
  (c) => HEBREW[(c.toLowerCase().charCodeAt(0) - 97) % HEBREW.length]));

const each = (catalogue, f) => Object.fromEntries(Object.entries(catalogue).map(([key, message]) => [key,
  typeof message === 'string' ? f(message) : Object.fromEntries(Object.entries(message).map(([k, v]) => [k, f(v)]))]));

/** The two pseudo-languages' catalogues from English's: `{ 'en-XA': …, 'ar-XB': … }`. */
export const pseudoLanguages = (english) => ({ 'en-XA': each(english, longer), 'ar-XB': each(english, rightToLeft) });
