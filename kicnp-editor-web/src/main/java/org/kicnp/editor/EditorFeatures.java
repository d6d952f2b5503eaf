package org.kicnp.editor;

/** The features this build of the editor has; filled in as the XML and script components join the build. */
final class EditorFeatures {
    private EditorFeatures() {
    }

    static Features available() {
        return new Features(Features.noXml(), Features.noScripts());
    }
}
