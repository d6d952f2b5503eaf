/**
 * The paper's "simple sentence parser for K-ICNP using the technique of Case Grammar (Bruce, 1975)": a tokenizer,
 * a lexicon, and a verb-centred case grammar that turn what a user says into a {@link org.kicnp.language.CaseFrame}
 * (or a polite {@link org.kicnp.language.ParseResult.NotUnderstood}); {@link org.kicnp.language.CaseFrames} makes
 * an instance frame of it, {@link org.kicnp.language.LanguageFrames} gives the class frames, and
 * {@link org.kicnp.language.ParserAgent} is the service agent that does all of this on the network. No NLP library:
 * the grammar is small, deterministic and takes microseconds per sentence. See {@code docs/language.md}.
 */
package org.kicnp.language;
