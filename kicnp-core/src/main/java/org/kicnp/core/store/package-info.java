/**
 * Durable storage for a knowledge base: a directory of the paper's XML files plus an append-only journal in
 * {@code .kicnp/}. Every acknowledged change is in the journal, forced to disk, before the knowledge base shows it;
 * compaction folds the journal back into the XML files through temporary files, a manifest and atomic renames, so
 * that a crash at any point leaves every file readable and loses nothing that was acknowledged. See
 * {@code docs/storage.md} for the layout and the recovery rules.
 */
package org.kicnp.core.store;
