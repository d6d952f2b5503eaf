package org.kicnp.editor;

/** The features of this build of the editor: XML transfer through kicnp-core, the script check through kicnp-script. */
final class EditorFeatures {
    private EditorFeatures() {
    }

    static Features available() {
        ScriptCheck scripts = new ScriptCheck();
        return new Features(new XmlTransfer(scripts), scripts, Features.noInference());
    }
}
