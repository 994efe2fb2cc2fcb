package rp1.simulator.record;

/** The names and version numbers of the recording format (docs/recording.md), for its writer and reader. */
final class RecordingFormat {
    /** The first word of a recording. */
    static final String MAGIC = "rp1-recording";
    /** The format version: raise it when the layout of the lines changes. */
    static final int VERSION = 1;

    static final String WORLD_MODEL = "world-model";
    static final String SEED = "seed";
    static final String PROPERTY = "property";
    static final String PLAN = "plan";
    /** Prefix of each line of the floor-plan text. */
    static final String PLAN_LINE = "|";
    static final String CLIENT = "client";
    static final String INPUT = "input";
    static final String BROKEN = "broken";
    static final String END = "end";

    private RecordingFormat() {
    }
}
