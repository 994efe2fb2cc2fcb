package rp1.simulator.record;

import java.awt.Color;
import java.io.IOException;
import java.util.Base64;

import rp1.rossum.RsBody;
import rp1.rossum.RsConnection;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.ViewAction;
import rp1.simulator.session.Request;

/**
 * The text form of the inputs a recording keeps (docs/recording.md): a kind word, then the input's
 * values. A client's body is kept as the bytes of its body specification, in Base64, so it comes
 * back with the part ids it had.
 */
final class InputText {
    private InputText() {
    }

    /** Appends the kind and values of {@code r} to {@code line}. */
    static void write(TextLine line, Request r) {
        if (r instanceof Request.Body b) {
            line.word("body").word(Base64.getEncoder().encodeToString(RsConnection.encodeBodySpecification(b.body())));
        } else if (r instanceof Request.Departure) {
            line.word("departure");
        } else if (r instanceof Request.Timeout t) {
            line.word("timeout").real(t.duration()).integer(t.index());
        } else if (r instanceof Request.Subscription s) {
            line.word("subscription").integer(s.code()).integer(s.index()).bool(s.enable());
        } else if (r instanceof Request.SensorStatus s) {
            line.word("sensor-status").integer(s.sensorId());
        } else if (r instanceof Request.Motion m) {
            RsMotionRequest q = m.motion();
            line.word("motion").real(q.linearVelocity).real(q.rotationalVelocity).real(q.duration);
        } else if (r instanceof Request.ActuatorControl a) {
            writeActuatorControl(line, a);
        } else if (r instanceof Request.Halt) {
            line.word("halt");
        } else if (r instanceof Request.Position) {
            line.word("position");
        } else if (r instanceof Request.Placement p) {
            line.word("placement").text(p.name());
        } else if (r instanceof Request.TargetSelection t) {
            line.word("target-selection").bool(t.random()).text(t.name()).bool(t.status()).bool(t.exclusive());
        } else if (r instanceof Request.Plan) {
            line.word("plan");
        } else if (r instanceof Request.Heartbeat h) {
            line.word("heartbeat").real(h.interval());
        } else if (r instanceof Request.PainterChange p) {
            writePainterChange(line, p);
        } else if (r instanceof Request.EncoderStatus e) {
            writeEncoderStatus(line, e);
        } else {
            throw new IllegalArgumentException("no text form for the request " + r);
        }
    }

    private static void writeActuatorControl(TextLine line, Request.ActuatorControl a) {
        String[] names = a.namesCopy();
        double[] values = a.valuesCopy();
        line.word("actuator-control").integer(a.actuatorId()).integer(a.commandId()).integer(values.length);
        for (int i = 0; i < values.length; i++) {
            line.text(i < names.length ? names[i] : null).real(values[i]);
        }
    }

    private static void writePainterChange(TextLine line, Request.PainterChange p) {
        line.word("painter-change").integer(p.painterId()).bool(p.erasure()).bool(p.activation())
                .bool(p.trailerDefined()).real(p.xTrailer()).real(p.yTrailer()).real(p.wTrailer());
        Color[] colors = p.colors();
        if (colors == null) {
            line.word("-");
            return;
        }
        line.integer(colors.length);
        for (Color c : colors) {
            line.color(c);
        }
    }

    private static void writeEncoderStatus(TextLine line, Request.EncoderStatus e) {
        int[] ids = e.idsCopy();
        line.word("encoder-status").integer(e.requestIndex()).bool(e.clear()).integer(ids.length);
        for (int id : ids) {
            line.integer(id);
        }
    }

    /** Appends the kind and values of a view action. */
    static void write(TextLine line, ViewAction a) {
        if (a instanceof ViewAction.MouseClick m) {
            line.word("mouse-click").integer(m.button()).integer(m.clickCount()).real(m.x()).real(m.y());
        } else if (a instanceof ViewAction.RemovePaintTrails) {
            line.word("remove-paint-trails");
        } else {
            throw new IllegalArgumentException("no text form for the view action " + a);
        }
    }

    /** Reads a client's request (kind and values) from the rest of the line. */
    static Request readRequest(LineCursor in) throws RecordingException {
        String kind = in.word("the kind of request");
        return switch (kind) {
            case "body" -> new Request.Body(body(in));
            case "departure" -> new Request.Departure();
            case "timeout" -> new Request.Timeout(in.real("timeout duration"), in.smallInteger("timeout index"));
            case "subscription" -> new Request.Subscription(in.smallInteger("event code"), in.smallInteger("event index"),
                    in.bool("enable"));
            case "sensor-status" -> new Request.SensorStatus(in.smallInteger("sensor id"));
            case "motion" -> new Request.Motion(new RsMotionRequest(in.real("linear velocity"),
                    in.real("rotational velocity"), in.real("duration")));
            case "actuator-control" -> actuatorControl(in);
            case "halt" -> new Request.Halt();
            case "position" -> new Request.Position();
            case "placement" -> new Request.Placement(in.text("placement name"));
            case "target-selection" -> new Request.TargetSelection(in.bool("random"), in.text("target name"),
                    in.bool("status"), in.bool("exclusive"));
            case "plan" -> new Request.Plan();
            case "heartbeat" -> new Request.Heartbeat(in.real("heartbeat interval"));
            case "painter-change" -> painterChange(in);
            case "encoder-status" -> encoderStatus(in);
            default -> throw in.error("unknown request \"" + kind + "\"");
        };
    }

    /** Reads a view action (kind and values) from the rest of the line. */
    static ViewAction readViewAction(LineCursor in) throws RecordingException {
        String kind = in.word("the kind of view action");
        return switch (kind) {
            case "mouse-click" -> new ViewAction.MouseClick(in.smallInteger("button"), in.smallInteger("click count"),
                    in.real("x"), in.real("y"));
            case "remove-paint-trails" -> new ViewAction.RemovePaintTrails();
            default -> throw in.error("unknown view action \"" + kind + "\"");
        };
    }

    private static RsBody body(LineCursor in) throws RecordingException {
        String text = in.word("the body specification");
        byte[] bytes;
        try {
            bytes = Base64.getDecoder().decode(text);
        } catch (IllegalArgumentException e) {
            throw in.error("the body specification is not valid Base64: " + e.getMessage());
        }
        try {
            return RsConnection.decodeBodySpecification(bytes);
        } catch (IOException e) {
            throw in.error("the body specification is damaged: " + e.getMessage());
        }
    }

    private static Request actuatorControl(LineCursor in) throws RecordingException {
        int actuator = in.smallInteger("actuator id");
        int command = in.smallInteger("command id");
        int n = count(in, "parameter count");
        String[] names = new String[n];
        double[] values = new double[n];
        for (int i = 0; i < n; i++) {
            names[i] = in.text("parameter name");
            values[i] = in.real("parameter value");
        }
        return new Request.ActuatorControl(actuator, command, names, values);
    }

    private static Request painterChange(LineCursor in) throws RecordingException {
        int id = in.smallInteger("painter id");
        boolean erasure = in.bool("erasure");
        boolean activation = in.bool("activation");
        boolean trailerDefined = in.bool("trailer defined");
        double x = in.real("trailer x");
        double y = in.real("trailer y");
        double w = in.real("trailer width");
        String first = in.word("colour count");
        Color[] colors = null;
        if (!first.equals("-")) {
            int n = count(in, first, "colour count");
            colors = new Color[n];
            for (int i = 0; i < n; i++) {
                colors[i] = in.color("colour");
            }
        }
        return new Request.PainterChange(id, erasure, activation, trailerDefined, x, y, w, colors);
    }

    private static Request encoderStatus(LineCursor in) throws RecordingException {
        int index = in.smallInteger("request index");
        boolean clear = in.bool("clear on report");
        int n = count(in, "encoder count");
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = in.smallInteger("encoder id");
        }
        return new Request.EncoderStatus(index, ids, clear);
    }

    /** A count of items that follow on the line (never more than the line could hold). */
    private static int count(LineCursor in, String what) throws RecordingException {
        return count(in, in.word(what), what);
    }

    private static int count(LineCursor in, String word, String what) throws RecordingException {
        int n;
        try {
            n = Integer.parseInt(word);
        } catch (NumberFormatException e) {
            throw in.error(what + ": an integer was expected, found \"" + word + "\"");
        }
        if (n < 0 || n > 100_000) {
            throw in.error(what + ": " + n + " is out of range");
        }
        return n;
    }
}
