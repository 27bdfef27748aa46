(function(){
  var A = JSON.parse(document.getElementById('kanat-animation').textContent);
  function f32(b64){var s = atob(b64), u = new Uint8Array(s.length);
    for (var i = 0; i < s.length; i++) u[i] = s.charCodeAt(i); return new Float32Array(u.buffer);}
  var P = f32(A.positions), B = A.n_bodies ? f32(A.bodies) : null, V = f32(A.vessel), T = f32(A.track);
  var gd = document.getElementById(A.plot), slider = document.getElementById(A.plot + '-slider');
  var label = document.getElementById(A.plot + '-time'), button = document.getElementById(A.plot + '-play');
  var follow = document.getElementById(A.plot + '-follow');
  var nf = A.times.length, nn = A.nodes, timer = null;
  function pick(arr, start, count, o){var x = [], y = [], z = [];
    for (var i = 0; i < count; i++){var p = (start + i) * 3; x.push(arr[p] - o[0]); y.push(arr[p+1] - o[1]);
      z.push(arr[p+2]);}
    return [x, y, z];}
  function show(k){
    var o = follow.checked ? [V[3 * k], V[3 * k + 1]] : [0, 0];
    var xs = [], ys = [], zs = [], off = k * nn;
    function add(q){xs.push(q[0]); ys.push(q[1]); zs.push(q[2]);}
    A.cables.forEach(function(c){add(pick(P, off, c.count, o)); off += c.count;});
    if (A.n_bodies) add(pick(B, k * A.n_bodies, A.n_bodies, o));
    add(pick(V, k, 1, o)); add(pick(T, 0, T.length / 3, o));
    Plotly.restyle(gd, {x: xs, y: ys, z: zs}, A.traces);
    gd.setAttribute('data-frame', String(k)); slider.value = k;
    label.textContent = 't = ' + A.times[k].toFixed(1) + ' s';
  }
  function frame(){
    var r = follow.checked ? A.follow_ranges : A.earth_ranges;
    Plotly.relayout(gd, {'scene.xaxis.range': r[0], 'scene.yaxis.range': r[1], 'scene.aspectratio': r[2],
      'scene.xaxis.title.text': follow.checked ? 'x from the vessel [m]' : 'x [m]',
      'scene.yaxis.title.text': follow.checked ? 'y from the vessel [m]' : 'y [m]'});
    show(+gd.getAttribute('data-frame'));
  }
  function stop(){clearInterval(timer); timer = null; button.textContent = '\u25B6 play';}
  button.addEventListener('click', function(){
    if (timer){stop(); return;}
    button.textContent = '\u275A\u275A pause';
    timer = setInterval(function(){show((+gd.getAttribute('data-frame') + 1) % nf);}, A.interval_ms);
  });
  slider.addEventListener('input', function(){if (timer) stop(); show(+slider.value);});
  follow.addEventListener('change', frame);
  if (follow.checked) frame();
  window.KANAT.animation = {show: show, frames: nf, frame: frame};
})();
