package org.triad.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * A self-contained HTML page (inline data and JavaScript, no external resources) replaying a trace on a
 * canvas with play/pause, a time slider and a speed selector; each robot's battery is a gauge beside it and a figure
 * beside the time, at every frame.
 */
public final class HtmlReplay {

    private HtmlReplay() {
    }

    /** Samples a frame every 0.1 s of virtual time. */
    public static void write(Simulation sim, Path file) {
        write(sim, file, 0.1);
    }

    /**
     * @param frameSeconds virtual seconds between sampled frames, &gt; 0
     * @throws IllegalArgumentException on a bad interval or an empty trace
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void write(Simulation sim, Path file, double frameSeconds) {
        Checks.notNull("simulation", sim);
        Checks.notNull("file", file);
        Checks.positive("frame interval (s)", frameSeconds);
        List<TraceFrame> frames = sim.trace().frames();
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("the simulation has no recorded frames (trace off or no step taken)");
        }
        String html = TEMPLATE.replace("/*DATA*/", data(sim, Math.max(1, (int) Math.round(frameSeconds / sim.stepSeconds()))));
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            Files.writeString(file, html, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file, e);
        }
    }

    private static String data(Simulation sim, int stride) {
        FloorPlan plan = sim.plan();
        Trace trace = sim.trace();
        StringBuilder b = new StringBuilder("{\"bounds\":");
        Rect r = plan.bounds();
        b.append('[').append(n(r.minX())).append(',').append(n(r.minY())).append(',').append(n(r.maxX())).append(',')
                .append(n(r.maxY())).append("],\"wall\":").append(n(plan.wallThickness())).append(",\"rooms\":[");
        join(b, plan.rooms(), (sb, room) -> sb.append('[').append(s(room.name())).append(',').append(n(room.bounds().minX()))
                .append(',').append(n(room.bounds().minY())).append(',').append(n(room.bounds().maxX())).append(',')
                .append(n(room.bounds().maxY())).append(',').append(room.corridor()).append(']'));
        b.append("],\"walls\":[");
        join(b, plan.walls(), (sb, w) -> sb.append('[').append(n(w.a().x())).append(',').append(n(w.a().y())).append(',')
                .append(n(w.b().x())).append(',').append(n(w.b().y())).append(']'));
        b.append("],\"doors\":[");
        join(b, plan.doorways(), (sb, d) -> sb.append('[').append(s(d.name())).append(',').append(n(d.end1().x()))
                .append(',').append(n(d.end1().y())).append(',').append(n(d.end2().x())).append(',')
                .append(n(d.end2().y())).append(']'));
        b.append("],\"waypoints\":[");
        join(b, plan.waypoints(), (sb, w) -> sb.append('[').append(s(w.name())).append(',').append(n(w.position().x()))
                .append(',').append(n(w.position().y())).append(']'));
        b.append("],\"robots\":[");
        join(b, sim.robots(), (sb, x) -> sb.append('[').append(s(x.name())).append(',').append(n(x.radius())).append(']'));
        b.append("],\"people\":[");
        join(b, trace.personNames(), (sb, x) -> sb.append('[').append(s(x)).append(',')
                .append(n(sim.person(x).radius())).append(']'));
        b.append("],\"items\":[");
        join(b, trace.itemNames(), (sb, x) -> sb.append(s(x)));
        b.append("],\"events\":[");
        join(b, trace.events(), (sb, e) -> sb.append('[').append(n(e.time())).append(',').append(s(e.actor())).append(',')
                .append(s(e.action())).append(',').append(n(e.position().x())).append(',').append(n(e.position().y()))
                .append(',').append(e.success()).append(',').append(s(e.detail())).append(']'));
        b.append("],\"frames\":[");
        List<TraceFrame> frames = trace.frames();
        for (int i = 0; i < frames.size(); i += stride) {
            TraceFrame f = frames.get(i);
            if (i > 0) {
                b.append(',');
            }
            b.append('[').append(n(f.time())).append(",[");
            for (int k = 0; k < f.robotX().length; k++) {
                b.append(k > 0 ? "," : "").append(n(f.robotX()[k])).append(',').append(n(f.robotY()[k])).append(',')
                        .append(n(f.robotHeading()[k]));
            }
            b.append("],");
            xy(b, f.personX(), f.personY());
            b.append(',');
            xy(b, f.itemX(), f.itemY());
            b.append(",[");
            for (int k = 0; k < f.doorOpen().length; k++) {
                b.append(k > 0 ? "," : "").append(f.doorOpen()[k] ? 1 : 0);
            }
            b.append("],[");
            for (int k = 0; k < f.robotBattery().length; k++) {
                b.append(k > 0 ? "," : "").append(String.format(Locale.ROOT, "%.1f", f.robotBattery()[k]));
            }
            b.append("]]");
        }
        return b.append("]}").toString();
    }

    private static void xy(StringBuilder b, double[] xs, double[] ys) {
        b.append('[');
        for (int k = 0; k < xs.length; k++) {
            b.append(k > 0 ? "," : "").append(Double.isNaN(xs[k]) ? "null,null" : n(xs[k]) + "," + n(ys[k]));
        }
        b.append(']');
    }

    private static <T> void join(StringBuilder b, List<T> list, java.util.function.BiConsumer<StringBuilder, T> each) {
        for (int i = 0; i < list.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            each.accept(b, list.get(i));
        }
    }

    private static String n(double v) {
        return String.format(Locale.ROOT, "%.3f", v);
    }

    /** A JSON string literal that is also safe inside a script element. */
    private static String s(String v) {
        StringBuilder b = new StringBuilder("\"");
        for (char c : v.toCharArray()) {
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (c < 0x20 || c == '<' || c == '>' || c == '&') {
                b.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.append('"').toString();
    }

    private static final String TEMPLATE = """
            <!DOCTYPE html>
            <html lang="en"><head><meta charset="utf-8"><title>Triad simulation replay</title>
            <style>body{font-family:sans-serif;margin:10px}#log{font-family:monospace;font-size:12px;white-space:pre;
            max-height:220px;overflow:auto;border:1px solid #ccc;padding:4px}canvas{border:1px solid #999}</style></head>
            <body><div><button id="play">Pause</button> <input id="slider" type="range" min="0" value="0" style="width:60%">
            <select id="speed"><option>1</option><option>2</option><option selected>5</option><option>10</option>
            <option>30</option></select>x <span id="time"></span></div><canvas id="c"></canvas><div id="log"></div>
            <script>
            const D=/*DATA*/;
            const cv=document.getElementById('c'),g=cv.getContext('2d'),B=D.bounds,S=Math.min(40,1100/(B[2]-B[0]));
            cv.width=(B[2]-B[0])*S+20;cv.height=(B[3]-B[1])*S+20;
            const X=x=>10+(x-B[0])*S,Y=y=>10+(B[3]-y)*S;
            const slider=document.getElementById('slider');slider.max=D.frames.length-1;
            let playing=true,idx=0,acc=0,last=null;
            function line(a,b,c,d){g.beginPath();g.moveTo(X(a),Y(b));g.lineTo(X(c),Y(d));g.stroke();}
            function disc(x,y,r,col){g.fillStyle=col;g.beginPath();g.arc(X(x),Y(y),Math.max(2,r*S),0,7);g.fill();}
            function draw(){const f=D.frames[idx];g.fillStyle='#fff';g.fillRect(0,0,cv.width,cv.height);
             for(const r of D.rooms){g.fillStyle=r[5]?'#e1e8f0':'#f5f5f0';g.fillRect(X(r[1]),Y(r[4]),(r[3]-r[1])*S,(r[4]-r[2])*S);
              g.fillStyle='#555';g.font='11px sans-serif';g.fillText(r[0],X(r[1])+3,Y(r[4])+12);}
             g.strokeStyle='#282828';g.lineWidth=Math.max(1,D.wall*S);for(const w of D.walls)line(...w);
             D.doors.forEach((d,i)=>{g.strokeStyle=f[4][i]?'#3caa3c':'#d22828';g.lineWidth=f[4][i]?1:Math.max(2,D.wall*S);
              if(f[4][i]){g.setLineDash([3,3]);line(d[1],d[2],d[3],d[4]);g.setLineDash([]);}else line(d[1],d[2],d[3],d[4]);});
             for(const w of D.waypoints)disc(w[1],w[2],0.05,'#bbb');
             g.strokeStyle='#96afeb';g.lineWidth=2;D.robots.forEach((r,k)=>{g.beginPath();for(let i=0;i<=idx;i++){
              const q=D.frames[i][1];if(q.length>3*k){i?g.lineTo(X(q[3*k]),Y(q[3*k+1])):g.moveTo(X(q[3*k]),Y(q[3*k+1]));}}g.stroke();});
             for(let i=0;i<f[3].length;i+=2)if(f[3][i]!==null){g.fillStyle='#8c3caa';const s=Math.max(4,0.2*S);
              g.fillRect(X(f[3][i])-s/2,Y(f[3][i+1])-s/2,s,s);g.fillText(D.items[i/2],X(f[3][i])+s,Y(f[3][i+1]));}
             for(let i=0;i<f[2].length;i+=2)if(f[2][i]!==null){disc(f[2][i],f[2][i+1],D.people[i/2][1],'#f08c14');
              g.fillStyle='#333';g.fillText(D.people[i/2][0],X(f[2][i])+6,Y(f[2][i+1])-6);}
             D.robots.forEach((r,k)=>{if(f[1].length>3*k){const x=f[1][3*k],y=f[1][3*k+1],h=f[1][3*k+2];disc(x,y,r[1],'#1e50c8');
              g.strokeStyle='#fff';g.lineWidth=2;line(x,y,x+Math.cos(h)*r[1],y+Math.sin(h)*r[1]);
              if(f[5].length>k){const b=f[5][k],gx=X(x)+r[1]*S+4,gy=Y(y)-4;g.fillStyle='#fff';g.fillRect(gx,gy,30,8);
               g.fillStyle=b<20?'#d22828':'#3caa3c';g.fillRect(gx,gy,30*Math.max(0,Math.min(100,b))/100,8);
               g.strokeStyle='#141414';g.lineWidth=1;g.strokeRect(gx,gy,30,8);g.fillStyle='#141414';
               g.fillText(Math.round(b)+' %',gx+33,gy+8);}}});
             for(const e of D.events)if(e[0]<=f[0]){disc(e[3],e[4],0.12,e[5]?'#008c3c':'#d21e1e');}
             document.getElementById('time').textContent='t = '+f[0].toFixed(1)+' s, '+(D.robots.length==1?(f[5].length?'battery '+f[5][0].toFixed(1)+' %':''):
              D.robots.map((r,k)=>f[5].length>k?r[0]+' '+f[5][k].toFixed(1)+' %':'').filter(x=>x).join(', '));slider.value=idx;
             document.getElementById('log').textContent=D.events.filter(e=>e[0]<=f[0]).map(e=>
              e[0].toFixed(2).padStart(8)+'s '+e[1].padEnd(8)+(e[5]?' ok   ':' FAIL ')+e[2]+(e[5]||!e[6]?'':' - '+e[6])).join('\\n');}
            function tick(ts){if(last!==null&&playing){acc+=(ts-last)/1000*parseFloat(document.getElementById('speed').value);
              const dt=D.frames.length>1?D.frames[1][0]-D.frames[0][0]:1;while(acc>=dt&&idx<D.frames.length-1){acc-=dt;idx++;}draw();}
             last=ts;requestAnimationFrame(tick);}
            document.getElementById('play').onclick=e=>{playing=!playing;e.target.textContent=playing?'Pause':'Play';};
            slider.oninput=()=>{idx=+slider.value;draw();};draw();requestAnimationFrame(tick);
            </script></body></html>
            """;
}
