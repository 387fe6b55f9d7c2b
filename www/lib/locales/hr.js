/** The Croatian (hr) strings of the UI: every key of English (lib/strings.js). */
export default {
  "app.name": "splinelab",
  "app.galleryTitle": "{app} — {heading}",
  "app.demoTitle": "{title} — {app}",
  "app.tagline":
    "Parametarske krivulje koje možete povlačiti: svaki algoritam kolegija kao živa slika.",
  "app.backToGallery": "← Sve demonstracije",
  "app.loading": "Učitavanje biblioteke krivulja…",
  "app.noSimd":
    "Ovaj preglednik ne može pokrenuti biblioteku krivulja: potreban je WebAssembly SIMD (Chrome ili Edge 91, Firefox 89, Safari 16.4 ili noviji).",
  "app.wasmFailed":
    "Biblioteka krivulja nije se mogla učitati ({message}). Pokrenite `make build`, zatim ponovno učitajte stranicu.",
  "app.unknownDemo": "Ne postoji demonstracija „{id}”. Prikazuje se galerija.",
  "app.footer": "Sav se izračun odvija u vašem pregledniku (Rust preveden u WebAssembly).",
  "gallery.heading": "Demonstracije po poglavljima nastavnog programa",
  "gallery.open": "Otvori demonstraciju",
  "gallery.thumbnailAlt": "Pregled: {title}",
  "section.1": "1 · Parametarske krivulje",
  "section.2": "2 · Bézierove krivulje",
  "section.3": "3 · B-krivulje",
  "section.4": "4 · Racionalne krivulje i NURBS",
  "section.5": "5 · Interpolacijske krivulje",
  "section.6": "6 · Površine",
  "toolbar.label": "Alati demonstracije",
  "toolbar.undo": "Poništi",
  "toolbar.undo.title": "Poništi (Ctrl+Z)",
  "toolbar.redo": "Ponovi",
  "toolbar.redo.title": "Ponovi (Ctrl+Shift+Z)",
  "toolbar.reset": "Ispočetka",
  "toolbar.reset.title": "Natrag na početnu sliku",
  "toolbar.fit": "Prilagodi",
  "toolbar.fit.title":
    "Prilagodi prikaz slici (povucite prazan prostor za pomicanje, kotačić ili dva prsta za zumiranje)",
  "toolbar.share": "Podijeli poveznicu",
  "toolbar.share.title": "Kopirajte poveznicu koja vraća upravo ovu sliku",
  "toolbar.svg": "SVG",
  "toolbar.svg.title": "Izvezi sliku kao SVG",
  "toolbar.tikz": "TikZ",
  "toolbar.tikz.title": "Izvezi sliku kao TikZ/PGF: datoteka .tex koju prevodi pdflatex",
  "toolbar.png": "PNG",
  "toolbar.png.title": "Izvezi sliku kao PNG (2×, bijela pozadina)",
  "toolbar.json": "JSON",
  "toolbar.json.title": "Izvezi stanje kao JSON",
  "toolbar.import": "Uvezi",
  "toolbar.import.title": "Učitaj stanje iz datoteke JSON",
  "toolbar.lecture": "Predavanje",
  "toolbar.lecture.title": "Veliki tekst i debele linije za projekciju",
  "toolbar.export": "Izvoz:",
  "shell.controls": "Upravljanje",
  "shell.formula": "Formula",
  "shell.whatYouSee": "Što vidite",
  "shell.tryThis": "Isprobajte",
  "shell.figureHelp3d":
    "Povucite točku (u ravnini okrenutoj prema vama) ili je odaberite tipkom Tab: strelice je pomiču (Shift: 10 px), PageUp/PageDown prema vama ili od vas. Povucite prazan prostor za okretanje, Shift i povlačenje, povlačenje desnom tipkom miša ili dva prsta za pomicanje, kotačić ili dva prsta za zumiranje; kad nijedna točka nije odabrana, strelice okreću prikaz.",
  "shell.figureHelp3dTyped":
    "Krivulja slijedi formule upisane u ploči s kontrolama. Povucite za okretanje, Shift i povlačenje, povlačenje desnom tipkom miša ili dva prsta za pomicanje, kotačić ili dva prsta za zumiranje; strelice okreću prikaz.",
  "shell.figureHelp":
    "Povucite točku ili je odaberite tipkom Tab i pomičite strelicama (Shift: 10 px). Povucite prazan prostor za pomicanje prikaza; kotačić ili dva prsta za zumiranje.",
  "shell.figureHelpTyped":
    "Krivulja slijedi formule upisane u ploči s kontrolama. Povucite sliku za pomicanje prikaza; kotačić ili dva prsta za zumiranje.",
  "shell.openInPlayground": "Otvori za slobodno isprobavanje",
  "handles.roleDescription": "interaktivna slika",
  "handles.selected": "Odabrano: {label}, ({x}; {y})",
  "handles.moved": "{label} premješteno u ({x}; {y})",
  "handles.selected3d": "Odabrano: {label}, ({x}; {y}; {z})",
  "handles.moved3d": "{label} premješteno u ({x}; {y}; {z})",
  "scene3d.legend.gaussian": "Gaussova zakrivljenost K",
  "scene3d.legend.mean": "srednja zakrivljenost H",
  "status.linkCopied": "Poveznica je kopirana u međuspremnik.",
  "status.linkShown": "Kopirajte ovu poveznicu: {url}",
  "status.imported": "Uvezeno: „{name}”.",
  "status.exported": "Spremljeno: {name}.",
  "status.badLink":
    "Ova se poveznica nije mogla pročitati ({message}); zadržava se trenutna slika.",
  "status.importTooLarge":
    "„{name}” ima {size} MB; datoteke veće od {max} MB ne uvoze se (stanje ima nekoliko kilobajta).",
  "status.badImport": "„{name}” nije se moglo uvesti ({message}); zadržava se trenutna slika.",
  "status.rejected": "Ta je promjena odbijena: {message}",
  "status.nothingToUndo": "Nema se što poništiti.",
  "status.nothingToRedo": "Nema se što ponoviti.",
  "format.quoted": "„{value}”",
  "error.notObject": "stanje mora biti objekt JSON",
  "error.unknownField": "nepoznato polje „{field}”",
  "error.missingField": "nedostaje polje „{field}”",
  "error.notFinite": "polje „{field}” mora biti konačan broj, dobiveno {value}",
  "error.notInteger": "polje „{field}” mora biti cijeli broj, dobiveno {value}",
  "error.range": "polje „{field}” mora biti između {min} i {max}, dobiveno {value}",
  "error.notBoolean": "polje „{field}” mora biti true ili false, dobiveno {value}",
  "error.notString": "polje „{field}” mora biti jedno od {choices}, dobiveno {value}",
  "error.notArray": "polje „{field}” mora biti lista",
  "error.count": "polje „{field}” mora imati između {min} i {max} elemenata, dobiveno {count}",
  "error.pointShape": "polje „{field}”: točka {index} mora biti par [x, y]",
  "error.pointShape3": "polje „{field}”: točka {index} mora biti trojka [x, y, z]",
  "error.gridCount":
    "polje „{field}” mora imati {rows} × {cols} = {expected} točaka (retci duž u), dobiveno {count}",
  "error.camera":
    "polje „view” mora biti kamera [azimut, elevacija, udaljenost, x, y, z]: konačni brojevi, udaljenost > 0, |elevacija| ≤ 89°",
  "error.pointFinite": "polje „{field}”: točka {index} ima koordinatu koja nije konačan broj",
  "error.knots": "polje „{field}”: {message}",
  "error.window":
    "polje „view” mora sadržavati četiri konačna broja [xmin, ymin, xmax, ymax] uz xmin < xmax i ymin < ymax",
  "error.badEncoding": "stanje u poveznici nije valjano (oštećeno ili odrezano)",
  "error.badJson": "nije valjan JSON: {message}",
  "error.version": "nepodržana inačica datoteke {version} (ova stranica čita inačicu {expected})",
  "error.wrongDemo": "datoteka je za demonstraciju „{found}”, a ne „{expected}”",
  "error.attribute": "atribut „{name}”: {message}",
  "error.recordShape":
    "„{value}” mora imati po jedan tekst za svako od {fields}, odvojene zarezima",
  "error.unknownDemo": "ne postoji demonstracija „{id}”",
  "control.t": "Parametar t",
  "control.t.input": "vrijednost t (decimalni broj ili razlomak poput 1/3)",
  "control.play": "Pokreni",
  "control.pause": "Pauza",
  "control.stepBack": "Korak natrag",
  "control.stepForward": "Korak",
  "control.stepBack.title": "t − 1/16",
  "control.stepForward.title": "t + 1/16",
  "control.addPoint": "Dodaj točku",
  "control.addPoint.title": "Dodajte točku iza odabrane (+)",
  "control.removePoint": "Ukloni točku",
  "control.removePoint.title": "Uklonite odabranu točku (Delete)",
  "control.construction": "Prikaži konstrukciju",
  "control.badNumber": "„{value}” nije broj",
  "curve.degree.1": "linearna",
  "curve.degree.2": "kvadratna",
  "curve.degree.3": "kubna",
  "curve.degree.4": "kvartična",
  "curve.degree.5": "kvintična",
  "curve.degree.n": "stupnja {n}",
  "deCasteljau.title": "De Casteljauov algoritam",
  "deCasteljau.summary":
    "Ponovljena linearna interpolacija gradi točku P(t) Bézierove krivulje; crta se svaka razina trokuta.",
  "deCasteljau.aria":
    "{kind} Bézierova krivulja s kontrolnim točkama (broj: {count}); t = {t}; točka P(t) = ({x}; {y})",
  "deCasteljau.degree": "Stupanj n = {n} (kontrolne točke: {count})",
  "deCasteljau.tableCaption": "De Casteljauov trokut za t = {t}: redak r sadrži točke razine r",
  "deCasteljau.tableLevel": "r = {r}",
  "deCasteljau.pointLabel": "P(t)",
  "deCasteljau.minPoints": "najmanji broj kontrolnih točaka Bézierove krivulje ovdje je {min}",
  "deCasteljau.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "deCasteljau.whatYouSee":
    "Bézierova krivulja (plavo) i njezin kontrolni poligon (sivo, iscrtkano). Za parametar t svaka se stranica poligona dijeli u omjeru t : (1 − t); nove točke (razina 1) čine kraći poligon koji se ponovno dijeli, dok ne ostane jedna točka: točka P(t) na krivulji (crveno-narančasto). Početna slika je riješeni primjer iz grčkih bilježaka (poglavlje 2 nastavnog programa): P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2) uz t = 1/4 daje P(t) = (29/16; 23/16).",
  "deCasteljau.try1":
    "Pritisnite Pokreni i gledajte kako konstrukcija klizi duž poligona dok P(t) iscrtava krivulju.",
  "deCasteljau.try2":
    "Povucite P₂ i pogledajte koji se dio krivulje najviše pomiče: Bernsteinova težina točke P₂ najveća je za t = 2/3.",
  "deCasteljau.try3":
    "Odaberite točku tipkom Tab i pritisnite + da dodate novu: stupanj raste, a trokut dobiva razinu više.",
  "bernstein.title": "Bernsteinova baza",
  "bernstein.summary":
    "Težine iza Bézierove krivulje: svaki Bᵢⁿ(t) nacrtan ispod krivulje, zbroj im je 1, a svaki je najveći za t = i/n.",
  "bernstein.aria":
    "{kind} Bézierova krivulja s kontrolnim točkama (broj: {count}) i ispod nje njezine Bernsteinove bazne funkcije stupnja {n} (njih {count}); t = {t}; težine {values} (zbroj {sum}); točka P(t) = ({x}; {y})",
  "bernstein.ariaPeak": "; istaknuta {b}: najveća za t = {t}, gdje je krivulja u ({x}; {y})",
  "bernstein.degree": "Stupanj n = {n} (kontrolne točke: {count}, bazne funkcije: {count})",
  "bernstein.pointLabel": "P(t)",
  "bernstein.peakPointLabel": "P({t})",
  "bernstein.peakLabel": "maks. za t = {t}",
  "bernstein.marker": "t = {t}",
  "bernstein.axisT": "t",
  "bernstein.axisValue0": "0",
  "bernstein.axisValue1": "1",
  "bernstein.formulaPeak": "najveća za",
  "bernstein.tableCaption":
    "Bernsteinove težine stupnja {n} za t = {t} (postavite pokazivač na redak ili ga fokusirajte da istaknete njegovu kontrolnu točku)",
  "bernstein.colFunction": "Bazna funkcija",
  "bernstein.colValue": "Bᵢⁿ(t)",
  "bernstein.colMirror": "Bₙ₋ᵢⁿ(1 − t) (simetrija)",
  "bernstein.colPeak": "Maksimum",
  "bernstein.rowName": "{b}, težina točke {p}",
  "bernstein.peakCell": "{value} za t = {t}",
  "bernstein.sumRow": "Zbroj",
  "bernstein.sumNote": "Zbroj težina (njih {count}) za t = {t}: {sum}",
  "bernstein.peakNote":
    "{b}, težina točke {p}, najveća je za t = {t}: pomicanje točke {p} najviše mijenja krivulju oko P({t}) = ({x}; {y}).",
  "bernstein.peakHint":
    "Postavite pokazivač na baznu funkciju na grafu ili na redak tablice, ili odaberite kontrolnu točku (Tab), da vidite gdje najviše djeluje.",
  "bernstein.minPoints": "najmanji broj kontrolnih točaka Bézierove krivulje ovdje je {min}",
  "bernstein.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "bernstein.whatYouSee":
    "Bézierova krivulja (plavo) s kontrolnim poligonom, a ispod nje grafovi njezinih Bernsteinovih baznih funkcija Bᵢⁿ(t) na 0 ≤ t ≤ 1, svaki u boji prstena oko svoje kontrolne točke Pᵢ. Točka P(t) (crveno-narančasto) zbroj je točaka Pᵢ težinski uzetih s vrijednostima u kojima oznaka siječe grafove; te težine nikad nisu negativne i uvijek daju zbroj 1. Bᵢⁿ ima jedan maksimum, za t = i/n: ondje pomicanje Pᵢ najviše mijenja krivulju (istaknuti pojas i P(i/n)). Početna slika je kubni riješeni primjer iz grčkih bilježaka (poglavlje 2 nastavnog programa) za t = 1/4, s težinama 27/64, 27/64, 9/64, 1/64.",
  "bernstein.try1":
    "Postavite pokazivač na zeleni graf B₁³ (ili odaberite P₁ tipkom Tab): maksimum mu je za t = 1/3, a pojas na krivulji pokazuje gdje P₁ najjače vuče; sada povucite P₁ i gledajte kako se taj dio pomiče.",
  "bernstein.try2":
    "Povucite oznaku na grafu (ili pritisnite Pokreni): težine se mijenjaju, ali redak Zbroj u tablici uvijek pokazuje 1. Usporedite dva srednja stupca: Bᵢⁿ(t) jednako je Bₙ₋ᵢⁿ(1 − t) (simetrija).",
  "bernstein.try3":
    "Pritisnite + da dodate kontrolne točke: grafovi postaju uži i niži, svaki i dalje s vrhom u i/n, pa svaka točka djeluje lokalnije.",
  "subdivision.title": "Podjela",
  "subdivision.summary":
    "Podijelite Bézierovu krivulju u t₀ na dvije Bézierove krivulje: njihovi su kontrolni poligoni stranice de Casteljauova trokuta; ponovljeno raspolavljanje konvergira prema krivulji.",
  "subdivision.aria":
    "{kind} Bézierova krivulja s kontrolnim točkama (broj: {count}) podijeljena u t₀ = {t} na lijevi poligon L₀…L{n} i desni poligon R₀…R{n}; točka podjele ({x}; {y})",
  "subdivision.ariaLevels":
    "; ponovljena podjela u 1/2, razina {k}: {polygons} poligona, ukupno kontrolnih točaka: {total}",
  "subdivision.control.t": "Podjela u t₀",
  "subdivision.control.t.input": "vrijednost t₀ (decimalni broj ili razlomak poput 1/3)",
  "subdivision.control.stepBack.title": "t₀ − 1/16",
  "subdivision.control.stepForward.title": "t₀ + 1/16",
  "subdivision.control.levels": "Ponovljeno raspolavljanje: razine",
  "subdivision.control.levels.input": "Broj razina podjele u 1/2 (od 0 do 6)",
  "subdivision.control.triangle": "Prikaži de Casteljauov trokut",
  "subdivision.levelsNote":
    "Razina {k}: {polygons} poligona, kontrolne točke: {total} (različite: {distinct}; susjedi dijele krajnju točku).",
  "subdivision.levelsNote0":
    "Razina 0: 1 poligon (sama krivulja), kontrolne točke: {total}. Povećajte broj razina da se svaki dio iznova raspolavlja u 1/2.",
  "subdivision.degree": "Stupanj n = {n} (kontrolne točke: {count})",
  "subdivision.leftLabel": "L{i}",
  "subdivision.rightLabel": "R{i}",
  "subdivision.firstLabel": "{p} = {l}",
  "subdivision.lastLabel": "{p} = {r}",
  "subdivision.splitLabel": "{l} = {r}",
  "subdivision.splitPointLabel": "P(t₀)",
  "subdivision.formulaPolygons.few": "poligona",
  "subdivision.formulaPolygons.one": "poligon",
  "subdivision.formulaPolygons.other": "poligona",
  "subdivision.formulaPoints": "kontrolnih točaka",
  "subdivision.tableCaption":
    "Kontrolne točke dviju polovica za t₀ = {t}: lijeve lᵢ (gornja stranica trokuta), desne rᵢ (hipotenuza)",
  "subdivision.colIndex": "i",
  "subdivision.colLeft": "Lijeva polovica, na [0, t₀]",
  "subdivision.colRight": "Desna polovica, na [t₀, 1]",
  "subdivision.minPoints": "najmanji broj kontrolnih točaka Bézierove krivulje ovdje je {min}",
  "subdivision.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "subdivision.whatYouSee":
    "Bézierova krivulja (plavo) presječena u t₀ (crveno-narančasta točka) na dvije Bézierove krivulje istog stupnja. Lijevi dio ima kontrolne točke L₀ … Lₙ (zeleno, puna linija), prvu točku svake razine de Casteljauova trokuta (njegova gornja stranica); desni dio ima R₀ … Rₙ (ljubičasto, iscrtkano, kvadratići), zadnju točku svake razine (hipotenuza); ostatak trokuta nacrtan je blijedo. Uz razine iznad 0 svaki se dio iznova raspolavlja u 1/2: nakon k razina 2ᵏ malih poligona prianja uz krivulju, zbog čega ponovljena podjela konvergira prema njoj. Početna slika je kubni riješeni primjer iz grčkih bilježaka (poglavlje 2 nastavnog programa); za t₀ = 1/4 polovice se spajaju u (29/16; 23/16).",
  "subdivision.try1":
    "Upišite 1/4 za t₀: tablica pokazuje lijeve točke riješenog primjera (0; 0), (1/2; 1/2), (9/8; 1), (29/16; 23/16) i desne točke (29/16; 23/16), (31/8; 11/4), (13/2; 7/2), (8; 2).",
  "subdivision.try2":
    "Povećajte broj razina na 3: osam poligona, već blizu krivulje; uz 5 ili 6 teško ih je razlikovati od nje.",
  "subdivision.try3":
    "Povucite t₀ prema 0: lijevi se poligon steže u točku P₀, a desni postaje izvorni poligon.",
  "flattening.title": "Adaptivna linearizacija",
  "flattening.summary":
    "Bézierova krivulja nacrtana kao izlomljena linija koja ostaje unutar tolerancije ε: kratki segmenti gdje se savija, dugi gdje je ravna.",
  "flattening.tolerance": "Tolerancija ε (jedinice svijeta)",
  "flattening.tolerance.input": "tolerancija ε, od {min} do {max}",
  "flattening.badTolerance":
    "tolerancija ε: „{value}” nije broj od {min} do {max}; zadržava se trenutna vrijednost",
  "flattening.flattenFailed":
    "izlomljena linija nije se mogla izračunati ({message}); prikazuje se posljednja",
  "flattening.band": "Prikaži pojas tolerancije (širine 2ε)",
  "flattening.presets": "Oblici",
  "flattening.preset.title": "Premjestite četiri kontrolne točke u ovaj oblik",
  "flattening.preset.s": "S-krivulja",
  "flattening.preset.loop": "Petlja",
  "flattening.preset.cusp": "Šiljak",
  "flattening.preset.straight": "Gotovo ravna",
  "flattening.segments.few": "{count} segmenta",
  "flattening.segments.one": "{count} segment",
  "flattening.segments.other": "{count} segmenata",
  "flattening.half": "Uz ε/2 = {tolerance}: broj segmenata {count} (× {ratio}; √2 ≈ 1,41)",
  "flattening.countLabel": "broj segmenata {count} uz ε = {tolerance}",
  "flattening.aria":
    "kubna Bézierova krivulja s kontrolnim točkama {points}, aproksimirana izlomljenom linijom uz toleranciju {tolerance}: segmenata: {count} (vrhova: {vertices}); uz toleranciju {half} segmenata: {halfCount}",
  "flattening.formula.whole": "cijela krivulja:",
  "flattening.formula.flat": "ravno: jedan segment",
  "flattening.formula.split": "podijeli",
  "flattening.formula.until": "dijeli dok svaki dio ne prođe test, zatim nacrtaj tetive:",
  "flattening.formula.segments": "segmenata",
  "flattening.whatYouSee":
    "Plava kubna krivulja nacrtana je kao narančasta izlomljena linija koju biblioteka vraća za toleranciju ε: svaka je točka krivulje unutar ε od nje, pa krivulja nikad ne izlazi iz sivog pojasa širine 2ε. Test je onaj iz grčkih bilježaka (poglavlje 2 nastavnog programa, „adaptivno crtanje”): dio je dovoljno ravan kad su mu unutarnje kontrolne točke unutar ε od tetive P₀P₃; inače se dio skraćuje i ponovno testira (biblioteka raspolavlja ili udvostručuje parametarski korak svakog dijela dok test ne omeđi granicu, pa treba malo segmenata). Gdje se krivulja savija, dijelovi su kratki, gdje je gotovo ravna, dovoljna je jedna duga tetiva, a prepolovljenje ε množi broj segmenata s otprilike √2.",
  "flattening.try1":
    "Povucite klizač tolerancije od 1 do 0,001 i gledajte kako se segmenti zgušnjavaju ondje gdje se krivulja najviše savija.",
  "flattening.try2":
    "Pritisnite „Petlja” i „Šiljak”: kratki se segmenti skupljaju na petlji i na oštrom vrhu, a ravni krajevi dobivaju duge.",
  "flattening.try3":
    "Pritisnite „Gotovo ravna”, zatim odmaknite P₁ od pravca: broj skače s nekoliko segmenata na mnogo.",
  "lineIntersection.title": "Presjek krivulje i pravca",
  "lineIntersection.summary":
    "Gdje pravac siječe Bézierovu krivulju, pronađeno dijeljenjem krivulje i odbacivanjem svakog pravokutnika koji pravac promašuje.",
  "lineIntersection.handleA": "A",
  "lineIntersection.handleB": "B",
  "lineIntersection.sameLinePoints":
    "polje „line”: dvije točke moraju biti različite, dvaput dobiveno ({x}; {y})",
  "lineIntersection.failed":
    "presjeci se nisu mogli izračunati ({message}); prikazuju se posljednji",
  "lineIntersection.depth": "Prikazana dubina rekurzije",
  "lineIntersection.depth.input": "dubina, cijeli broj od 0 do {max}",
  "lineIntersection.badDepth":
    "dubina: „{value}” nije cijeli broj od 0 do {max}; zadržava se trenutna dubina",
  "lineIntersection.shallower": "◀ Razina",
  "lineIntersection.shallower.title": "Prikaži razinu manje",
  "lineIntersection.deeper": "Razina ▶",
  "lineIntersection.deeper.title": "Prikaži razinu više",
  "lineIntersection.boxes":
    "Dubina {depth} od {deepest}. Posjećeni pravokutnici: {visited}; sijeku pravac: {hit}; odbačeni: {pruned}. Pravokutnici se ne dijele ispod {tolerance}.",
  "lineIntersection.none": "nema presjeka",
  "lineIntersection.count.few": "{count} presjeka",
  "lineIntersection.count.one": "{count} presjek",
  "lineIntersection.count.other": "{count} presjeka",
  "lineIntersection.crossings":
    "Pravac siječe kontrolni poligon {polygon} puta, a krivulju {curve} puta: pravac nikad ne siječe krivulju češće nego njezin poligon (smanjenje varijacije).",
  "lineIntersection.rootLabel": "t = {t}",
  "lineIntersection.aria":
    "kubna Bézierova krivulja s kontrolnim točkama {points} i pravac kroz A = {a} i B = {b}: {result}; pravac siječe kontrolni poligon {polygon} puta; pravokutnici rekurzije prikazani do dubine {depth} od {deepest}",
  "lineIntersection.tableCaption":
    "Presjeci poredani po t (svaka točka unutar {tolerance} od pravca)",
  "lineIntersection.tableNone": "Nema presjeka: pravac promašuje krivulju.",
  "lineIntersection.tableRoot": "korijen",
  "lineIntersection.tablePoint": "P(t)",
  "lineIntersection.formula.miss": "isti predznak u vrhovima pravokutnika",
  "lineIntersection.formula.pruned": "pravac promašuje pravokutnik: odbačen",
  "lineIntersection.formula.until": ", dok pravokutnik ne bude manji od",
  "lineIntersection.formula.split": "inače podijeli u",
  "lineIntersection.formula.curve": "krivulja",
  "lineIntersection.formula.polygon": "poligon",
  "lineIntersection.whatYouSee":
    "Kubna krivulja (plavo) i beskonačni pravac kroz A i B (zeleno). Pretraživanje iz grčkih bilježaka (poglavlje 2 nastavnog programa): uzmite pravokutnik oko kontrolnih točaka; ako ga pravac promašuje, nijedan dio krivulje unutar njega ne može sjeći pravac i pravokutnik se odbacuje (blijedo sivo); inače podijelite krivulju u t = 1/2 i promotrite obje polovice, dok pravokutnici (narančasti obrubi) ne budu manji od 0,001. Crveno-narančaste točke su presjeci koje vraća biblioteka (pročišćeni do 10⁻⁹ od pravca), označeni svojim t; kao što obećava svojstvo smanjenja varijacije, nikad ih nema više nego sjecišta s kontrolnim poligonom.",
  "lineIntersection.try1":
    "Postavite dubinu na 0 i pritišćite „Razina ▶” korak po korak: pravokutnici daleko od pravca otpadaju, ostali se stežu na tri sjecišta.",
  "lineIntersection.try2":
    "Povucite B prema gore dok pravac ne napusti krivulju: broj pada na 1, zatim na „nema presjeka”, a prvi je pravokutnik već odbačen.",
  "lineIntersection.try3":
    "Povucite P₁ i P₂ da izravnate kontrolni poligon: broj sjecišta s poligonom pada, a sjecišta s krivuljom nikad ih ne premašuju.",
  "joining.title": "Spajanje dviju krivulja",
  "joining.summary":
    "Dva kubna Bézierova segmenta spajaju se u spoju; pravilo (C0, C1, G1, C2) drži ih spojenima dok povlačite, a provjera javlja kontinuitet.",
  "joining.aria":
    "Dva kubna Bézierova segmenta, P za t ∈ [0, 1] i Q za t ∈ [1, 2]; pravilo {rule}; provjera: {verdict}; P′(1) = {dp}, Q′(1) = {dq}",
  "joining.ruleLegend": "Pravilo u spoju",
  "joining.rule.none": "nijedno (slobodno povlačenje)",
  "joining.rule.C0": "C⁰: segmenti se spajaju",
  "joining.rule.C1": "C¹: jednaka brzina",
  "joining.rule.G1": "G¹: ista tangenta",
  "joining.rule.C2": "C²: i jednaka akceleracija",
  "joining.checkerLegend": "Provjera kontinuiteta",
  "joining.verdict": "{c}, {g} u spoju",
  "joining.verdict.broken": "nije ni C⁰: segmenti se ne spajaju",
  "joining.verdict.infinite": "C∞: jedan polinom",
  "joining.legend.none":
    "Ništa se ne nameće: svaka se točka pomiče zasebno, a provjera javlja što je god spoj postao.",
  "joining.legend.C0":
    "Kvadratić označava točku koju postavlja pravilo: Q₀ = P₃. Povucite je i P₃ je slijedi.",
  "joining.legend.C1":
    "Kvadratići označavaju točke koje postavlja pravilo: Q₀ = P₃ i Q₁ = 2P₃ − P₂ (P₂ zrcaljena u spoju). Povucite kvadratić i umjesto njega slijedi lijevi segment.",
  "joining.legend.G1":
    "Kvadratići označavaju točke koje postavlja pravilo: Q₀ = P₃ i Q₁ na polupravcu iz P₂ kroz P₃. Q₁ klizi samo duž tog pravca: udaljenost joj je slobodna, pa brzina može skočiti.",
  "joining.legend.C2":
    "Kvadratići označavaju točke koje postavlja pravilo: Q₀, Q₁ i Q₂ = P₁ − 4P₂ + 4P₃. Produljene stranice P₁P₂ i Q₂Q₁ sijeku se u jednoj točki D (A-okvir).",
  "joining.free.none": "Slobodne: svih osam točaka.",
  "joining.free.C0": "Slobodne: P₀, P₁, P₂, Q₁, Q₂, Q₃ i spoj.",
  "joining.free.C1": "Slobodne: P₀, P₁, Q₂, Q₃, spoj i jedna od P₂, Q₁.",
  "joining.free.G1": "Slobodne: P₀, P₁, P₂, Q₂, Q₃, spoj i duljina Q₀Q₁.",
  "joining.free.C2":
    "Za dvije kubne krivulje C² ostavlja donekle slobodnima samo P₀ i Q₃: P₁, P₂ i spoj određuju Q₁ i Q₂.",
  "joining.leftArrow": "P′(1)",
  "joining.rightArrow": "Q′(1)",
  "joining.pointD": "D",
  "joining.arrowCaption":
    "Strelice: brzina P′(1) koja dolazi u spoj i Q′(1) koja iz njega izlazi, nacrtane na 1/6 duljine",
  "joining.tableCaption": "U spoju t = 1 (derivacije iz jezgre, P na [0, 1], Q na [1, 2])",
  "joining.row.p3-p2": "P₃ − P₂",
  "joining.row.q1-q0": "Q₁ − Q₀",
  "joining.row.dp": "P′(1)",
  "joining.row.dq": "Q′(1)",
  "joining.row.ddp": "P″(1)",
  "joining.row.ddq": "Q″(1)",
  "joining.formula.none":
    "Bez pravila: provjera uspoređuje P(1), P′(1), P″(1) s Q(1), Q′(1), Q″(1)",
  "joining.formula.rule": "pravilo:",
  "joining.formula.anyLength": "bilo koja duljina",
  "joining.formula.notG1": "smjerovi tangenti se razlikuju (ili se segmenti ne spajaju)",
  "joining.formula.checker": "provjera:",
  "joining.formula.notC0": "nije C⁰",
  "joining.whatYouSee":
    "Dva kubna Bézierova segmenta: P (plavo) za t ∈ [0, 1] i Q (zeleno) za t ∈ [1, 2], spojena u P₃ = Q₀. Odabrano pravilo iz poglavlja 2 nastavnog programa (grčke bilješke) održava se dok povlačite: točke koje ono određuje (kvadratići) slijede, a provjera kontinuiteta iz poglavlja 1 javlja kakav je spoj zapravo. Dvije strelice su brzine koje dolaze u spoj i izlaze iz njega: za C¹ su jednake, za G¹ samo imaju isti smjer. Za dvije kubne krivulje C² ostavlja donekle slobodnima samo P₀ i Q₃.",
  "joining.try1":
    "Uz C¹ povucite P₂ i gledajte kako je Q₁ zrcali kroz spoj; zatim odaberite G¹ i pomičite Q₁ duž iscrtkanog pravca: provjera pada na C⁰, G¹ jer strelice dobivaju različite duljine.",
  "joining.try2":
    "Odaberite „nijedno” i odmaknite Q₀ spoja od P₃: provjera javlja da se segmenti ni ne spajaju.",
  "joining.try3":
    "Odaberite C² i povucite P₁: Q₂ se pomiče zajedno s njom preko točke A-okvira D, a samo P₀ i Q₃ ostaju gdje ste ih postavili.",
  "bezierProperties.title": "Svojstva Bézierovih krivulja",
  "bezierProperties.summary":
    "Konveksna ljuska, afina invarijantnost, simetrija, povećanje stupnja i smanjenje varijacije, svako prikazano na jednoj krivulji koju možete povlačiti.",
  "bezierProperties.propertyLegend": "Svojstvo",
  "bezierProperties.property.hull": "Konveksna ljuska",
  "bezierProperties.property.affine": "Afino preslikavanje",
  "bezierProperties.property.reversed": "Obrnuti poredak (simetrija)",
  "bezierProperties.property.elevation": "Povećanje stupnja",
  "bezierProperties.property.variation": "Smanjenje varijacije",
  "bezierProperties.affineLegend": "Afino preslikavanje (oko težišta c)",
  "bezierProperties.rotation": "Rotacija (stupnjevi)",
  "bezierProperties.rotation.input": "rotacija u stupnjevima",
  "bezierProperties.scale": "Skaliranje",
  "bezierProperties.scale.input": "faktor skaliranja",
  "bezierProperties.shear": "Smicanje (x += k·y)",
  "bezierProperties.shear.input": "faktor smicanja k",
  "bezierProperties.elevationLegend": "Povećanje stupnja",
  "bezierProperties.elevations": "Povećanja",
  "bezierProperties.elevations.input": "broj povećanja stupnja (od 0 do 8)",
  "bezierProperties.lineA": "A",
  "bezierProperties.lineB": "B",
  "bezierProperties.lineDegenerate": "polje „line”: njegove dvije točke moraju biti različite",
  "bezierProperties.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "bezierProperties.minPoints": "najmanji broj kontrolnih točaka Bézierove krivulje ovdje je {min}",
  "bezierProperties.degree": "Stupanj n = {n} (kontrolne točke: {count})",
  "bezierProperties.note.hull":
    "Sivo područje je konveksna ljuska kontrolnih točaka: svaka je točka krivulje njihova težinska sredina, s težinama ≥ 0 čiji je zbroj 1.",
  "bezierProperties.note.affine":
    "Zeleno: krivulja preslikanih kontrolnih točaka (izgrađena u jezgri). Crvene točkice: točke plave krivulje preslikane jedna po jedna istom matricom. Leže na zelenoj krivulji.",
  "bezierProperties.note.reversed":
    "Narančasto, iscrtkano: krivulja kontrolnih točaka u obrnutom poretku Pₙ … P₀. Iste točke, suprotan smjer (strelice).",
  "bezierProperties.note.elevation":
    "Narančasto: kontrolni poligon nakon povećanja stupnja. Ista krivulja, jedna točka više po povećanju; poligon se primiče krivulji.",
  "bezierProperties.note.variation":
    "Povucite A i B da pomaknete pravac: nikad ne siječe krivulju češće nego kontrolni poligon.",
  "bezierProperties.readout.hull": "Ljuska, vrhovi: {k} ({names})",
  "bezierProperties.readout.affine": "Najveći razmak: {d}",
  "bezierProperties.readout.reversed": "Najveći razmak: {d}",
  "bezierProperties.readout.elevation": "Kontrolne točke: {count} ({n} + {e})",
  "bezierProperties.readout.variation": "Pravac siječe poligon {k} puta, krivulju {j} puta",
  "bezierProperties.formula.sum": "zbroj",
  "bezierProperties.formula.hullVertices": "vrhovi ljuske",
  "bezierProperties.formula.because": "jer",
  "bezierProperties.formula.samples": "uzorci",
  "bezierProperties.formula.forExample": "npr.",
  "bezierProperties.formula.points": "kontrolne točke",
  "bezierProperties.formula.lineCurve": "pravac ∩ krivulja",
  "bezierProperties.formula.linePolygon": "pravac ∩ poligon",
  "bezierProperties.tableCaption":
    "Nakon jednog povećanja: stupanj {n} → {m}, kontrolne točke Q₀ … Q{last}",
  "bezierProperties.aria.hull":
    "{kind} Bézierova krivulja unutar konveksne ljuske svojih kontrolnih točaka (vrhova ljuske: {k})",
  "bezierProperties.aria.affine":
    "{kind} Bézierova krivulja i njezina slika uz rotaciju {rotation}°, skaliranje {scale}, smicanje {shear}; preslikane točke krivulje leže na preslikanoj krivulji (najveći razmak {d})",
  "bezierProperties.aria.reversed":
    "{kind} Bézierova krivulja i krivulja njezinih obrnutih kontrolnih točaka nacrtana iscrtkano preko nje (najveći razmak {d})",
  "bezierProperties.aria.elevation":
    "{kind} Bézierova krivulja nakon povećanja stupnja ({e}): kontrolne točke: {count}, ista krivulja",
  "bezierProperties.aria.variation":
    "{kind} Bézierova krivulja i pravac: pravac siječe kontrolni poligon {k} puta, a krivulju {j} puta",
  "bezierProperties.whatYouSee":
    "Jedna Bézierova krivulja (plavo) i, jedno po jedno, svojstva navedena u poglavlju 2 nastavnog programa (iz grčkih bilježaka): ostaje unutar konveksne ljuske svojih kontrolnih točaka; afino preslikavanje kontrolnih točaka preslikava cijelu krivulju; točke u obrnutom poretku daju istu krivulju prijeđenu unatrag; povećanje stupnja dodaje kontrolnu točku bez promjene krivulje; a pravac ne siječe krivulju češće nego kontrolni poligon. Početak je riješeni primjer P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2).",
  "bezierProperties.try1":
    "Odaberite „Afino preslikavanje” i pomičite klizač smicanja: crvene točkice (preslikane točke krivulje) ostaju na zelenoj krivulji (izgrađenoj od preslikanih kontrolnih točaka).",
  "bezierProperties.try2":
    "Odaberite „Povećanje stupnja” i povećajte broj na 8: narančasti poligon ima 12 točaka i prianja uz krivulju.",
  "bezierProperties.try3":
    "Odaberite „Smanjenje varijacije” i povucite A i B tako da pravac siječe poligon što češće: krivulja se siječe najviše toliko puta.",
  "derivatives.title": "Derivacije i zakrivljenost",
  "derivatives.summary":
    "Brzina P′(t), normala, oskulacijska kružnica i predznačena zakrivljenost Bézierove krivulje, uz njezin hodograf.",
  "derivatives.aria":
    "{kind} Bézierova krivulja; t = {t}; P(t) = ({x}; {y}); brzina P′(t) = ({dx}; {dy}); zakrivljenost κ = {kappa}; hodograf je nacrtan desno",
  "derivatives.originLabel": "ishodište O",
  "derivatives.pointLabel": "P(t)",
  "derivatives.velocityLabel": "P′(t)",
  "derivatives.normalLabel": "N",
  "derivatives.straight": "Ovdje ravna (κ ≈ 0): nema oskulacijske kružnice",
  "derivatives.cusp": "Šiljak: P′(t) = 0, zakrivljenost je beskonačna",
  "derivatives.cuspShort": "šiljak",
  "derivatives.hodographCaption": "Hodograf P′(t) (stupanj {m}), ishodište O",
  "derivatives.scaleCaption": "Strelice brzine i hodograf nacrtani u mjerilu 1/{n}",
  "derivatives.curvatureLegend": "Zakrivljenost u t",
  "derivatives.readout": "κ(t) = {kappa}",
  "derivatives.radius": "Oskulacijska kružnica polumjera {r}, središte {side} od smjera kretanja",
  "derivatives.left": "lijevo (κ > 0: zakretanje suprotno od kazaljke na satu)",
  "derivatives.right": "desno (κ < 0: zakretanje u smjeru kazaljke na satu)",
  "derivatives.length": "Duljina luka L = {length}",
  "derivatives.degree": "Stupanj n = {n} (kontrolne točke: {count})",
  "derivatives.minPoints":
    "najmanji broj kontrolnih točaka u ovoj demonstraciji je {min} (kvadratna krivulja ili višeg stupnja)",
  "derivatives.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "derivatives.tableCaption": "Derivacije iz jezgre za t = {t} i kontrolne točke hodografa",
  "derivatives.row.point": "P(t)",
  "derivatives.row.dp": "P′(t)",
  "derivatives.row.ddp": "P″(t)",
  "derivatives.row.kappa": "κ(t)",
  "derivatives.row.radius": "polumjer 1/|κ|",
  "derivatives.row.dp0": "P′(0)",
  "derivatives.row.dp1": "P′(1)",
  "derivatives.row.length": "duljina luka",
  "derivatives.row.hodograph": "H{i} = {label}",
  "derivatives.whatYouSee":
    "Bézierova krivulja (plavo) s točkom P(t), njezinom brzinom P′(t) (crveno-narančasta strelica), jediničnom normalom N i oskulacijskom kružnicom (narančasto), kružnicom koja prianja uz krivulju u P(t), polumjera 1/|κ|. Desno je hodograf (zeleno, poglavlje 2 nastavnog programa, iz grčkih bilježaka): krivulja koju opisuje brzina, Bézierova krivulja za jedan stupanj niža čije su kontrolne točke n(P₁ − P₀), n(P₂ − P₁), …; strelica iz njezina ishodišta O isti je vektor P′(t). Početak je riješeni primjer P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2).",
  "derivatives.try1":
    "Postavite t na 0, a zatim na 1: brzina je 3(P₁ − P₀) = (6; 6) na početku i 3(P₃ − P₂) = (6; −6) na kraju — prva i zadnja stranica poligona hodografa.",
  "derivatives.try2":
    "Povucite P₂ ispod pravca P₀P₃: krivulja skreće na drugu stranu, κ mijenja predznak, a kružnica skače na drugu stranu.",
  "derivatives.try3":
    "Pritisnite Pokreni i gledajte kako strelica hodografa klizi duž njegove krivulje dok tangentna strelica putuje duž krivulje: uvijek su isti vektor.",
  "knotRuler.selected": "odabran uzao {label}, {u}",
  "knotRuler.moved": "uzao {label} pomaknut u {u}",
  "knotRuler.valueMultiple": "{u} (×{r})",
  "knotRuler.break": "prekid",
  "knotRuler.domain": "domena [u{p}, u{n1}] = [{a}; {b}]",
  "bsplineBasis.title": "Bazne funkcije B-krivulje",
  "bsplineBasis.summary":
    "Svaka Nᵢ,ₚ iz Cox–de Boorove rekurzije, nacrtana ispod krivulje iznad ravnala uzlova koje možete povlačiti: lokalni nosač, zbroj 1 i trokut vrijednosti u u.",
  "bsplineBasis.aria":
    "{kind} B-krivulja s kontrolnim točkama (broj: {count}) i uzlovima [{knots}]; za u = {u} (interval [{a}; {b})) bazne funkcije različite od nule su {values}, zbroj {sum}; točka C(u) = ({x}; {y}); sve bazne funkcije nacrtane su ispod krivulje, iznad ravnala uzlova",
  "bsplineBasis.ariaContinuity": "; kontinuitet u unutarnjim uzlovima: {list}",
  "bsplineBasis.ariaSupport": "; istaknuta {name}: nosač [{a}; {b})",
  "bsplineBasis.degreeLegend": "Stupanj p",
  "bsplineBasis.degreeOption": "{p}",
  "bsplineBasis.control.u": "Parametar u",
  "bsplineBasis.control.u.input": "vrijednost u iz domene (decimalni broj ili razlomak poput 5/2)",
  "bsplineBasis.sumNote": "Σ Nᵢ,ₚ({u}) = {sum}",
  "bsplineBasis.knotNote":
    "Kontrolne točke: {count}, stupanj p = {p}: uzlovi u₀ … u{last}, njih {m} (m + 1 = n + p + 2). Promjena stupnja ili broja točaka vraća uzlove na stegnuti uniformni vektor.",
  "bsplineBasis.resetKnots": "Stegnuti uniformni uzlovi",
  "bsplineBasis.resetKnots.title":
    "Zamijenite uzlove s p + 1 jednakih krajnjih uzlova i jednoliko razmaknutim unutarnjim uzlovima",
  "bsplineBasis.rulerHelp":
    "Ravnalo uzlova (ispod grafa): povucite uzao — ne može prijeći susjede; dvoklikom ili tipkom Enter na njega se stapa sljedeći uzao; Delete razdvaja skupinu. Tab nakon posljednje kontrolne točke odabire uzlove.",
  "bsplineBasis.minPoints":
    "B-krivulja stupnja {degree} treba najmanje ovoliko kontrolnih točaka: {min}",
  "bsplineBasis.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "bsplineBasis.fewPoints":
    "polje „points”: B-krivulja stupnja {p} treba najmanje ovoliko kontrolnih točaka: {need}, dobiveno {count}",
  "bsplineBasis.uRange": "polje „u” mora ležati u domeni [{a}; {b}], dobiveno {u}",
  "bsplineBasis.multiplicity.max": "u{i} već ima najveću višestrukost, p + 1 = {max}",
  "bsplineBasis.multiplicity.ends": "nije preostao nijedan unutarnji uzao koji bi se stopio s u{i}",
  "bsplineBasis.multiplicity.single": "u{i} je jednostruki uzao: nema se što razdvojiti",
  "bsplineBasis.pointLabel": "C(u)",
  "bsplineBasis.marker": "u = {u}",
  "bsplineBasis.axisValue0": "0",
  "bsplineBasis.axisValue1": "1",
  "bsplineBasis.axisU": "u",
  "bsplineBasis.formulaOtherwise": "inače",
  "bsplineBasis.tableCaption":
    "Bazne funkcije stupnja {p} za u = {u} (postavite pokazivač na redak ili ga fokusirajte da istaknete njegov nosač)",
  "bsplineBasis.colFunction": "Bazna funkcija",
  "bsplineBasis.colSupport": "Nosač [uᵢ, uᵢ₊ₚ₊₁)",
  "bsplineBasis.colValue": "Nᵢ,ₚ(u)",
  "bsplineBasis.rowName": "{name}, težina točke {point}",
  "bsplineBasis.supportCell": "[u{i}, u{j}) = [{a}; {b})",
  "bsplineBasis.sumRow": "Zbroj",
  "bsplineBasis.triangleCaption":
    "Cox–de Boorov trokut za u = {u}: interval k = {k}, [u{kSub}, u{k1Sub}) = [{a}; {b}); redak r sadrži vrijednosti stupnja r za i = k − r … k, svaku izračunatu iz dviju iznad nje",
  "bsplineBasis.triangleCorner": "stupanj r",
  "bsplineBasis.triangleRow": "r = {r}",
  "bsplineBasis.whatYouSee":
    "B-krivulja (plavo) iznad svojeg kontrolnog poligona; ispod nje grafovi njezinih baznih funkcija Nᵢ,ₚ(u), svaki u boji prstena oko svoje kontrolne točke Pᵢ; ispod grafa ravnalo uzlova s uzlovima u₀ … u_m i domenom [uₚ, uₙ₊₁] (plava traka). Točka C(u) zbroj je točaka Pᵢ težinski uzetih s vrijednostima u kojima oznaka siječe grafove: najviše p + 1 njih različito je od nule i zbroj im je uvijek 1. Svaka je Nᵢ,ₚ jednaka nuli izvan svojeg nosača [uᵢ, uᵢ₊ₚ₊₁), pa Pᵢ pomiče samo taj dio krivulje. Početak je kvadratni primjer iz hrvatskih bilježaka (poglavlje 3 nastavnog programa): U = [0, 0, 0, 1, 2, 3, 4, 4, 4], gdje su za u = 5/2 vrijednosti 1/8, 3/4, 1/8 — ondje je N₃,₂ = (−2u² + 10u − 11)/2 (u bilješkama je tiskarska pogreška +11).",
  "bsplineBasis.try1":
    "Postavite pokazivač na ljubičasti graf N₂,₂ (ili odaberite P₂ tipkom Tab): njegov je nosač [0, 3) osjenčan, a povlačenje P₂ pomiče samo taj dio krivulje.",
  "bsplineBasis.try2":
    "Povucite u₄ (uzao u 2) na ravnalu prema u₅: grafovi oko njega se rastežu i stišću, zaustavlja se u 3, a oznaka iznad njega mijenja se iz C¹ u C⁰ kad se dva uzla spoje — ili dvoklikom na u₄ stopite ih u jednom koraku.",
  "bsplineBasis.try3":
    "Odaberite stupanj 3: uzlovi postaju [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], svaki se graf širi na četiri intervala, a trokut dobiva redak više — zbroj je i dalje 1.",
  "deBoor.title": "De Boorov algoritam",
  "deBoor.summary":
    "Ponovljena interpolacija p + 1 aktivnih kontrolnih točaka gradi točku C(u) B-krivulje; uzlovi određuju svaki omjer α.",
  "deBoor.aria":
    "{kind} B-krivulja s kontrolnim točkama (broj: {count}), uzlovi {knots}; u = {u} u intervalu k = {k}, [{uk}; {uk1}); točka C(u) = ({x}; {y})",
  "deBoor.degree": "Stupanj p = {p}, kontrolne točke: {count}, {segments}",
  "deBoor.spans.few": "{count} neprazna intervala",
  "deBoor.spans.one": "{count} neprazan interval",
  "deBoor.spans.other": "{count} nepraznih intervala",
  "deBoor.span": "k = {k}: u ∈ [u{ks}, u{ks1}) = [{uk}; {uk1})",
  "deBoor.spanCaption": "interval [u{k}, u{k1})",
  "deBoor.uCaption": "u = {u}",
  "deBoor.multiplicity": "×{r}",
  "deBoor.tableCaption":
    "De Boorov trokut za u = {u} (interval k = {k}): redak r sadrži dⱼʳ, j = r … p, s α svojeg koraka",
  "deBoor.tableLevel": "r = {r}",
  "deBoor.alphaCell": "α = {value}",
  "deBoor.pointLabel": "C(u)",
  "deBoor.control.u": "Parametar u",
  "deBoor.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 3/2)",
  "deBoor.control.stepBack.title": "u − 1/16 domene",
  "deBoor.control.stepForward.title": "u + 1/16 domene",
  "deBoor.control.degree": "Stupanj p",
  "deBoor.control.degree.input": "stupanj p (od 1 do 5)",
  "deBoor.control.knots": "Vektor uzlova U (upišite i pritisnite Enter)",
  "deBoor.knotsHelp":
    "Broj nepadajućih uzlova: {m} (točke: {count}, stupanj {p}; m + 1 = n + p + 2).",
  "deBoor.control.clamped": "Stegnuti uniformni uzlovi",
  "deBoor.control.clamped.title": "p + 1 jednakih uzlova na svakom kraju, između njih 1, 2, …",
  "deBoor.control.addPoint.title":
    "Dodajte točku iza odabrane (+); uzlovi postaju stegnuti uniformni",
  "deBoor.control.removePoint.title":
    "Uklonite odabranu točku (Delete); uzlovi postaju stegnuti uniformni",
  "deBoor.knotsReset": "Vektor uzlova vraćen je na stegnuti uniformni za nove točke ili stupanj.",
  "deBoor.degreeRange": "stupanj mora biti cijeli broj od 1 do {max}, dobiveno „{value}”",
  "deBoor.minPoints": "najmanji broj kontrolnih točaka B-krivulje ovdje je {min}",
  "deBoor.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "deBoor.error.degree":
    "polje „degree” je {p}, ali uz kontrolne točke ({count}) najveći je stupanj {count} − 1",
  "deBoor.error.knotCount":
    "polje „knots” mora imati n + p + 2 = {expected} elemenata za točke ({count}) stupnja {p}, dobiveno {got}",
  "deBoor.error.knotOrder":
    "polje „knots” ne smije padati: element {index} je {value} nakon {previous}",
  "deBoor.error.multiplicity":
    "polje „knots”: uzao {value} pojavljuje se više od p + 1 = {max} puta",
  "deBoor.error.domain": "polje „knots”: domena [u{p}, u{n1}] = [{a}; {b}] je prazna",
  "deBoor.whatYouSee":
    "Iscrtkani sivi poligon sadrži sve kontrolne točke; sudjeluje samo p + 1 aktivnih točaka intervala koji sadrži u (puna siva linija). Svaka obojena razina interpolira prethodnu vlastitim omjerom α, očitanim iz vektora uzlova, dok ne ostane jedna točka C(u) — de Boorov algoritam iz poglavlja 3 nastavnog programa (konvencija hrvatskih i talijanskih bilježaka). Uz uzlove 0 0 0 0 1 1 1 1 svaki je α jednak u i to je de Casteljauova konstrukcija.",
  "deBoor.try1":
    "Pritisnite Pokreni i gledajte kako aktivne točke skaču kad u prijeđe uzao na traci ispod slike.",
  "deBoor.try2":
    "Uklanjajte točke dok ne ostanu četiri, zatim upišite uzlove 0 0 0 0 1 1 1 1 i u = 1/4: svaki je α jednak 1/4, a trokut je de Casteljauov (za P₀ … P₃ = (0; 0), (2; 2), (6; 4), (8; 2) završava u (29/16; 23/16)).",
  "deBoor.try3":
    "Upišite ponovljeni unutarnji uzao, npr. 0 0 0 0 1 2 2 4 4 4 4: neki α postaju 0 ili 1, a krivulja prolazi bliže kontrolnoj točki.",
  "knotVectors.title": "Vrste vektora uzlova",
  "knotVectors.summary":
    "Jedan kontrolni poligon, tri vektora uzlova: stegnute krivulje počinju u P₀, nestegnute ne, a zatvorene se glatko vraćaju na početak.",
  "knotVectors.aria":
    "{kind} B-krivulje na istim kontrolnim točkama (broj: {count}): stegnuti uzlovi {clamped}, stegnuta krivulja počinje u {c0}; nestegnuta uniformna krivulja počinje u {u0}; P₀ = {p0}; zatvorena krivulja prolazi kroz ciklus točaka",
  "knotVectors.degree": "Stupanj p = {p}, kontrolne točke: {count}",
  "knotVectors.degreeRange": "stupanj mora biti cijeli broj od 1 do {max}, dobiveno „{value}”",
  "knotVectors.minPoints": "najmanji broj kontrolnih točaka B-krivulje ovdje je {min}",
  "knotVectors.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "knotVectors.error.degree":
    "polje „degree” je {p}, ali uz kontrolne točke ({count}) najveći je stupanj {count} − 1",
  "knotVectors.control.degree": "Stupanj p",
  "knotVectors.control.degree.input": "stupanj p (od 1 do 5)",
  "knotVectors.control.spacing": "Unutarnji uzlovi stegnutog vektora",
  "knotVectors.control.show": "Prikazane krivulje",
  "knotVectors.spacing.uniform": "uniformno: 1, 2, …, n − p",
  "knotVectors.spacing.chord": "duljina tetiva: zbrojevi |Pᵢ₊₁ − Pᵢ|",
  "knotVectors.spacing.centripetal": "centripetalno: zbrojevi √|Pᵢ₊₁ − Pᵢ|",
  "knotVectors.show.clamped": "Otvorena neperiodička (stegnuta) — puna plava",
  "knotVectors.show.unclamped": "Nestegnuta uniformna — iscrtkana zelena",
  "knotVectors.show.closed": "Zatvorena (periodička) — točkasta ljubičasta",
  "knotVectors.legend.clamped": "otvorena neperiodička (stegnuta)",
  "knotVectors.legend.clamped.uniform": "stegnuta uniformna",
  "knotVectors.legend.clamped.chord": "stegnuta, razmak po duljini tetiva",
  "knotVectors.legend.clamped.centripetal": "stegnuta, centripetalni razmak",
  "knotVectors.legend.unclamped": "nestegnuta uniformna",
  "knotVectors.legend.closed": "zatvorena (periodička)",
  "knotVectors.style.clamped": "puna",
  "knotVectors.style.unclamped": "iscrtkana",
  "knotVectors.style.closed": "točkasta",
  "knotVectors.column.curve": "Krivulja",
  "knotVectors.column.knots": "Vektor uzlova u₀ … uₘ",
  "knotVectors.column.domain": "Domena [uₚ, uₙ₊₁]",
  "knotVectors.column.start": "Početak C(uₚ)",
  "knotVectors.column.end": "Kraj C(uₙ₊₁)",
  "knotVectors.tableCaption":
    "Vektori uzlova kako ih gradi jezgra te gdje svaka krivulja počinje i završava",
  "knotVectors.tex.clamped": "stegnuta",
  "knotVectors.tex.chord": "tetive",
  "knotVectors.tex.centripetal": "centripetalna",
  "knotVectors.tex.unclamped": "nestegnuta",
  "knotVectors.tex.closed": "zatvorena",
  "knotVectors.tex.domain": "domena",
  "knotVectors.tex.seam": "na šavu",
  "knotVectors.tex.lastRepeated": "zadnji p + 1 puta",
  "knotVectors.tex.legs": "članovi:",
  "knotVectors.whatYouSee":
    "Iste kontrolne točke nose tri B-krivulje istog stupnja. Stegnuti (otvoreni) uzlovi ponavljaju krajnje vrijednosti p + 1 puta, pa ta krivulja počinje u P₀ i završava u Pₙ; jednoliko razmaknuti nestegnuti uzlovi daju krivulju koja počinje i završava unutar poligona; zatvorena krivulja ponavlja prvih p točaka nakon posljednje, pa se zatvara s punim kontinuitetom C^(p−1) na šavu (na intervalima gdje koristi iste točke kao nestegnuta krivulja, dvije se podudaraju: točkice preko crtica). Razmak po duljini tetiva i centripetalni razmak pomiču unutarnje uzlove razmjerno stranicama poligona — poglavlje 3 nastavnog programa, prema grčkim i hrvatskim bilješkama.",
  "knotVectors.try1":
    "Postavite stupanj na 1: svaka krivulja postaje poligon (zatvorena sa svojom zatvarajućom stranicom); povećajte ga na 5 i gledajte kako se nestegnuta i zatvorena krivulja skupljaju unutar poligona.",
  "knotVectors.try2":
    "Odaberite duljinu tetiva i odvucite P₂ daleko: unutarnji uzlovi u tablici rastu sa susjednim stranicama.",
  "knotVectors.try3":
    "Povucite P₀: početak stegnute krivulje točno je slijedi, a početak nestegnute pomiče se samo za šestinu pomaka (za kubnu krivulju).",
  "localControl.title": "Lokalni nadzor i jaka konveksna ljuska",
  "localControl.summary":
    "Pomicanje jedne kontrolne točke B-krivulje mijenja samo p + 1 intervala; svaki interval ostaje unutar ljuske svojih p + 1 aktivnih točaka.",
  "localControl.control.u": "Parametar u",
  "localControl.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 5/2)",
  "localControl.control.point": "Istakni doseg Pᵢ, i =",
  "localControl.control.point.input": "indeks i točke čiji se doseg prikazuje",
  "localControl.control.degree": "Stupanj p",
  "localControl.control.degree.input": "stupanj p (od 1 do 5)",
  "localControl.error.tooFewPoints":
    "polje „points”: stupanj {p} treba najmanje ovoliko kontrolnih točaka: {min}, dobiveno {count}",
  "localControl.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "localControl.pointLabel": "C(u)",
  "localControl.formula.only": "samo se ovaj dio pomiče s",
  "localControl.formula.vertices.few": "vrha ljuske",
  "localControl.formula.vertices.one": "vrh ljuske",
  "localControl.formula.vertices.other": "vrhova ljuske",
  "localControl.readout.span": "Interval k = {k}: {names}",
  "localControl.readout.hull.few":
    "Samo ovih p + 1 točaka ovdje ima Nᵢ,ₚ(u) ≠ 0; njihova ljuska (osjenčana, {count} vrha) sadrži cijeli ovaj dio krivulje.",
  "localControl.readout.hull.one":
    "Samo ovih p + 1 točaka ovdje ima Nᵢ,ₚ(u) ≠ 0; njihova ljuska (osjenčana, {count} vrh) sadrži cijeli ovaj dio krivulje.",
  "localControl.readout.hull.other":
    "Samo ovih p + 1 točaka ovdje ima Nᵢ,ₚ(u) ≠ 0; njihova ljuska (osjenčana, {count} vrhova) sadrži cijeli ovaj dio krivulje.",
  "localControl.readout.support":
    "Pomicanje točke {name} mijenja C(u) samo za u ∈ [{lo}; {hi}; ostatak krivulje ostaje na mjestu.",
  "localControl.aria":
    "stegnuta {kind} B-krivulja s kontrolnim točkama (broj: {count}); {name} pomiče samo dio za u ∈ [{lo}; {hi}; u = {u} leži u intervalu {k}, aktivne točke {names}, ljuska s {hull}; točka C(u) = ({x}; {y})",
  "localControl.vertices.few": "{count} vrha",
  "localControl.vertices.one": "{count} vrhom",
  "localControl.vertices.other": "{count} vrhova",
  "localControl.tableCaption":
    "Sve bazne funkcije za u = {u} (stupanj {p}): samo istaknutih p + 1 redaka različito je od nule",
  "localControl.table.point": "točka",
  "localControl.table.value": "Nᵢ,{p}(u)",
  "localControl.table.support": "različita od nule za u ∈",
  "localControl.whatYouSee":
    "Stegnuta kubna B-krivulja (plavo), njezin kontrolni poligon (sivo, iscrtkano) i, ispod slike, njezini uzlovi kao crtice na pravcu parametra. Obojeni pojas označava dio krivulje koji zaokružena točka P_i može pomaknuti: parametre [u_i, u_{i+p+1}) gdje njezina bazna funkcija N_i,p nije nula; izvan njega krivulja se uopće ne pomiče (lokalni nadzor, poglavlje 3 nastavnog programa; hrvatske bilješke: pomak jedne točke utječe najviše na p + 1 segmenata). Sivo ispunjeno područje je konveksna ljuska p + 1 aktivnih točaka intervala koji sadrži u: cijeli taj dio krivulje leži unutar nje (jaka konveksna ljuska), a to je znatno uže područje od ljuske cijelog poligona (obrubljeno).",
  "localControl.try1":
    "Povucite P₄ i promatrajte krajeve krivulje: za u ∈ [0, 1] i [5, 6] ništa se ne pomiče, točno ondje gdje pojas prestaje.",
  "localControl.try2":
    "Upišite 5/2 za u: interval je k = 5, aktivne točke su P₂ … P₅ s težinama 1/48, 23/48, 23/48, 1/48, a C(u) leži unutar njihove osjenčane ljuske.",
  "localControl.try3":
    "Postavite stupanj na 1, a zatim na 5: pojas i aktivna ljuska rastu s p (p + 1 intervala, p + 1 točaka), a uz stupanj 1 krivulja je sam poligon.",
  "knotInsertion.title": "Umetanje uzla (Boehm) i izdvajanje Bézierovih segmenata",
  "knotInsertion.summary":
    "Umetnite uzao i krivulja zadržava oblik, dok kontrolni poligon dobiva točku i približava joj se; umetnite ih dovoljno i krivulja se raspada na Bézierove segmente.",
  "knotInsertion.control.u": "Uzao za umetanje, u",
  "knotInsertion.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 3/2)",
  "knotInsertion.control.insert": "Umetni",
  "knotInsertion.control.insert.title":
    "Umetnite jedanput uzao vrijednosti u (ili kliknite krivulju)",
  "knotInsertion.control.refine": "Raspolovi intervale",
  "knotInsertion.control.refine.title": "Umetnite polovište svakog nepraznog intervala",
  "knotInsertion.control.reset": "Natrag na izvornu",
  "knotInsertion.control.reset.title":
    "Uklonite sve umetnute uzlove (izvorne točke ostaju kakve jesu)",
  "knotInsertion.control.bezier": "Izdvoji Bézierove segmente",
  "knotInsertion.error.tooFewPoints":
    "polje „points”: stupanj {p} treba najmanje ovoliko kontrolnih točaka: {min}, dobiveno {count}",
  "knotInsertion.error.knotOrder":
    "polje „knots” ne smije padati (uzao {i} manji je od prethodnog)",
  "knotInsertion.error.emptyDomain": "polje „knots”: domena [u_p, u_n+1] je prazna",
  "knotInsertion.error.insertedRange": "polje „inserted”: {value} je izvan domene [{a}; {b}]",
  "knotInsertion.outside": "u = {value} je izvan domene [{a}; {b}]",
  "knotInsertion.refused": "taj se uzao ne može umetnuti: {message}",
  "knotInsertion.maxInserted":
    "ova demonstracija umeće najviše {max} uzlova; pritisnite „Natrag na izvornu” za novi početak",
  "knotInsertion.hoverLabel": "umetni u = {u}",
  "knotInsertion.formula.preview": "Umetanje bi koristilo:",
  "knotInsertion.readout": "Kontrolne točke: {count}, uzlovi: {knots}",
  "knotInsertion.segments.few": "{count} Bézierova segmenta (po jedan za svaki neprazan interval)",
  "knotInsertion.segments.one": "{count} Bézierov segment (po jedan za svaki neprazan interval)",
  "knotInsertion.segments.other":
    "{count} Bézierovih segmenata (po jedan za svaki neprazan interval)",
  "knotInsertion.segmentsOff": "Označite kućicu da se nacrta poligon svakog Bézierova segmenta.",
  "knotInsertion.knotsNow": "Uzlovi: {knots}",
  "knotInsertion.knotsNone":
    "Još nije umetnut nijedan uzao: kliknite krivulju ili pritisnite Umetni.",
  "knotInsertion.knotsBefore": "Uzlovi prije umetanja {s}: {knots}",
  "knotInsertion.knotsAfter": "Uzlovi nakon: {knots}",
  "knotInsertion.alphasPreview": "Umetanje {s} koristilo bi {alphas}",
  "knotInsertion.alphasUsed": "korišteni α: {alphas}",
  "knotInsertion.insertedList": "Umetnuti uzlovi ({count}), redom: {knots}",
  "knotInsertion.insertedNone": "Umetnuti uzlovi: nema",
  "knotInsertion.tableCaption":
    "Nove kontrolne točke nakon umetanja {s}: istaknute su nove, ostale su prepisane",
  "knotInsertion.tableEmpty": "Nove kontrolne točke pojavljuju se ovdje nakon umetanja.",
  "knotInsertion.aria":
    "{kind} B-krivulja s kontrolnim točkama (broj: {count}) i uzlovima (broj: {knots}) nakon umetanja u = {s} uz α = {alphas}; krivulja je nepromijenjena{segments}",
  "knotInsertion.ariaNone":
    "{kind} B-krivulja s kontrolnim točkama (broj: {count}) i uzlovima (broj: {knots}); umetanje u = {s} koristilo bi α = {alphas}{segments}",
  "knotInsertion.ariaSegments.few": "; prikazana {count} Bézierova segmenta",
  "knotInsertion.ariaSegments.one": "; prikazan {count} Bézierov segment",
  "knotInsertion.ariaSegments.other": "; prikazano {count} Bézierovih segmenata",
  "knotInsertion.whatYouSee":
    "Kvadratna B-krivulja iz primjera hrvatskih bilježaka (p = 2, uzlovi 0 0 0 1 2 3 4 4 4; poglavlje 3 nastavnog programa), nakon umetanja uzla 1,5. Umetanje uzla s Boehmovim pravilom zadržava prve točke, zamjenjuje njih p točkama Qᵢ na stranicama starog poligona (u omjeru αᵢ), a ostale pomiče: krivulja (plavo) uopće se ne mijenja, ali novi poligon (tamno, nove točke crveno-narančasto) ima točku više i leži bliže njoj; stari poligon ostaje blijed. Umetanje svakog unutarnjeg uzla dok ne dobije višestrukost p daje Bézierove segmente krivulje, po jedan za svaki neprazan interval.",
  "knotInsertion.try1":
    "Slika se otvara nakon umetanja u = 1,5: uzlovi su postali 0; 0; 0; 1; 1,5; 2; 3; 4; 4; 4, a α₂ = 3/4, α₃ = 1/4 sijeku stranice P₁P₂ i P₂P₃. Pritisnite „Natrag na izvornu”, zatim Umetni uz u = 1,5 da vidite kako se to događa.",
  "knotInsertion.try2":
    "Kliknite krivulju na nekoliko mjesta ili triput pritisnite „Raspolovi intervale”: poligon se primiče krivulji.",
  "knotInsertion.try3":
    "Označite „Izdvoji Bézierove segmente”: 5 segmenata, po jedan za svaki neprazan interval ([0; 1], [1; 1,5], [1,5; 2], [2; 3], [3; 4]); ponovno umetnite 1,5 i ništa se ne dodaje jer taj interval već postoji.",
  "multiplicity.title": "Višestrukost i kontinuitet",
  "multiplicity.summary":
    "Stapajte uzlove kubne B-krivulje i gledajte kako kontinuitet pada C², C¹, C⁰ (kut u kontrolnoj točki), a zatim prekid; ponovite kontrolnu točku i krivulja se privlači u nju.",
  "multiplicity.aria":
    "Kubna B-krivulja s kontrolnim točkama (broj: {count}) i uzlovima [{knots}]; u unutarnjim uzlovima (višestrukost: zajamčeno, izmjereno): {list}{through}{repeat}",
  "multiplicity.ariaThrough": "; krivulja prolazi kroz {point} za u = {u}",
  "multiplicity.ariaRepeat": "; ponovljena kontrolna točka: {points}, izmjereno {measured}",
  "multiplicity.knotLegend": "Višestrukost uzla",
  "multiplicity.knotReadout":
    "{names} = {u} · r = {r} · zajamčeno {guaranteed} · izmjereno {measured}",
  "multiplicity.noKnot": "Nema unutarnjeg uzla",
  "multiplicity.knotHint":
    "Odaberite uzao na ravnalu (kliknite ga ili Tab nakon posljednje kontrolne točke) da ga proučite; dvoklikom ili tipkom Enter na njega stapate sljedeći uzao.",
  "multiplicity.through":
    "Uz r = 3 krivulja prolazi kroz kontrolnu točku: C({u}) = {point}, s kutom.",
  "multiplicity.throughLabel": "C({u}) = {point}",
  "multiplicity.pointLabel": "C({u})",
  "multiplicity.jointLabel": "u = {u}",
  "multiplicity.raise": "Povećaj r (Enter)",
  "multiplicity.raise.title": "Stopite sljedeći uzao s proučavanim uzlom",
  "multiplicity.lower": "Smanji r (Delete)",
  "multiplicity.lower.title":
    "Pomaknite gornju kopiju proučavanog uzla na pola puta do sljedećeg uzla",
  "multiplicity.resetKnots": "Stegnuti uniformni uzlovi",
  "multiplicity.resetKnots.title":
    "Zamijenite uzlove s 4 jednaka krajnja uzla i jednoliko razmaknutim unutarnjim uzlovima",
  "multiplicity.multiplicity.max": "uzao već ima najveću višestrukost, p + 1 = {max}",
  "multiplicity.multiplicity.ends": "nije preostao nijedan unutarnji uzao koji bi se stopio s ovim",
  "multiplicity.multiplicity.single": "ovo je jednostruki uzao: nema se što razdvojiti",
  "multiplicity.repeatLegend": "Višestrukost kontrolne točke",
  "multiplicity.repeatOption": "×{k}",
  "multiplicity.repeatNone":
    "{point} se pojavljuje jednom. Odaberite kontrolnu točku i izaberite ×2 ili ×3 da je ponovite.",
  "multiplicity.repeatReadout": "{points}: kod u{k} = {u} izmjereno {measured}",
  "multiplicity.repeatEnd": "{points}: preblizu kraju krivulje za unutarnji uzao",
  "multiplicity.repeatHint":
    "Ponavljanje točke dodaje kontrolne točke, pa uzlovi ponovno postaju stegnuti uniformni.",
  "multiplicity.notesCaption":
    "Tablica iz hrvatskih bilježaka za kubne krivulje (trenutni slučajevi istaknuti)",
  "multiplicity.notesBreak": "diskontinuitet (odvojeni dijelovi)",
  "multiplicity.colMultiplicity": "Višestrukost",
  "multiplicity.colPoints": "Kontrolne točke",
  "multiplicity.colKnots": "Uzlovi",
  "multiplicity.knotsCaption":
    "Svaki unutarnji uzao: zajamčeno C^(p − r) iz vektora uzlova i ono što jezgra mjeri u spoju Bézierovih dijelova",
  "multiplicity.colKnot": "Uzao",
  "multiplicity.colR": "r",
  "multiplicity.colGuaranteed": "Zajamčeno",
  "multiplicity.colMeasured": "Izmjereno",
  "multiplicity.colPoint": "C(u)",
  "multiplicity.colThrough": "Prolazi kroz",
  "multiplicity.pointBreak": "lijevi dio završava u {left}, desni počinje u {right}",
  "multiplicity.formulaRule": "u uzlu višestrukosti",
  "multiplicity.formulaBreak": "prekid",
  "multiplicity.formulaMeasured": "izmjereno:",
  "multiplicity.whatYouSee":
    "Kubna B-krivulja (plavo) nad osam kontrolnih točaka i, ispod nje, njezino ravnalo uzlova: 0 0 0 0 1 2 3 4 5 5 5 5. Stapanje uzlova povećava višestrukost r uzla i kontinuitet ondje pada na C^(3 − r): uz r = 2 krivulja je C¹, uz r = 3 samo C⁰ — prolazi kroz kontrolnu točku i čini kut — a uz r = 4 raspada se na dva odvojena Bézierova dijela. Ponavljanje kontrolne točke umjesto toga zadržava parametarski C², ali trostruka točka zaustavlja krivulju (brzina nula) i daje kut, G⁰. Tablica je ona iz hrvatskih bilježaka (poglavlje 3 nastavnog programa); „izmjereno” je ono što jezgra nalazi uspoređujući derivacije Bézierovih dijelova u svakom spoju. Za dvostruku točku bilješke navode G¹; mjerenje daje G², jer zakrivljenost ostaje neprekinuta (pada na nulu u dvama uzlovima uz točku).",
  "multiplicity.try1":
    "Kliknite u₅ (uzao u 2) na ravnalu i triput pritisnite Enter: očitanje ide C¹, C⁰ — krivulja sada prolazi kroz P₄ s kutom — a zatim „prekid”.",
  "multiplicity.try2":
    "Odaberite P₄ i izaberite ×3: krivulja se privlači u točku i ondje skreće s kutom, izmjereno C² G⁰; uz ×2 samo se približi.",
  "multiplicity.try3":
    "Povucite uzao na ravnalu na njegova susjeda: kontinuitet napisan iznad njega pada čim se dva uzla spoje.",
  "matrixForm.title": "Matrični oblik uniformnih segmenata",
  "matrixForm.summary":
    "Svaki segment uniformne B-krivulje je [tᵖ … t 1] · M · (njegovih p + 1 točaka), s istom matricom M za svaki unutarnji segment.",
  "matrixForm.aria":
    "{kind} B-krivulja, {knots}, kontrolne točke: {count}; segment {i} za t = {t}: točka ({x}; {y}); {periodic}",
  "matrixForm.aria.periodic": "njegova je matrica periodička",
  "matrixForm.aria.notPeriodic": "njegova se matrica razlikuje od periodičke",
  "matrixForm.degree.2": "kvadratna (p = 2)",
  "matrixForm.degree.3": "kubna (p = 3)",
  "matrixForm.knots.uniform": "uniformni uzlovi (nestegnuti)",
  "matrixForm.knots.clamped": "stegnuti uzlovi",
  "matrixForm.control.degree": "Stupanj",
  "matrixForm.control.knots": "Vektor uzlova",
  "matrixForm.control.segment": "Segment i (ili kliknite krivulju)",
  "matrixForm.control.segment.input": "redni broj segmenta i",
  "matrixForm.control.t": "Lokalni parametar t",
  "matrixForm.segmentRange": "segment mora biti cijeli broj od 1 do {max}, dobiveno „{value}”",
  "matrixForm.periodic.yes": "Segment {i}: periodička matrica",
  "matrixForm.periodic.no": "Segment {i}: vlastita matrica",
  "matrixForm.degree": "Stupanj p = {p}, kontrolne točke: {count}, {segments}; uzlovi {knots}",
  "matrixForm.segments.few": "{count} segmenta",
  "matrixForm.segments.one": "{count} segment",
  "matrixForm.segments.other": "{count} segmenata",
  "matrixForm.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "matrixForm.minPoints": "stupanj {p} ovdje treba najmanje ovoliko kontrolnih točaka: {min}",
  "matrixForm.error.degree":
    "polje „degree” je {p}, ali uz kontrolne točke ({count}) najveći je stupanj {count} − 1",
  "matrixForm.matrixCaption":
    "M segmenta {i} (interval k = {k}), iz segmentMatrix(k): redak = potencija od t, stupac = točka koju množi",
  "matrixForm.resultCaption": "Točka za t, dvaput: umnožak gornjih brojeva i evaluate(u) iz jezgre",
  "matrixForm.result.product": "[tᵖ … 1] · M · točke",
  "matrixForm.result.evaluate": "evaluate(u)",
  "matrixForm.pointLabel": "C{i}(t)",
  "matrixForm.tex.periodic": "(periodički segment: uniformSegmentMatrix(p))",
  "matrixForm.tex.notPeriodic": "uniformSegmentMatrix(p): krajnji segment stegnutih uzlova",
  "matrixForm.tex.evaluate": "jezgra:",
  "matrixForm.whatYouSee":
    "Na jednom intervalu B-krivulja je polinom u lokalnom parametru t, pa se svaki segment može zapisati kao redak potencija od t, puta matrica M, puta p + 1 točaka koje ondje djeluju — matrični oblik iz hrvatskih bilježaka (poglavlje 3 nastavnog programa). Uz uniformne uzlove svaki segment ima istu M (bilješke ih zovu periodičkim segmentima): [[1/2, −1, 1/2], [−1, 1, 0], [1/2, 1/2, 0]] za kvadratne, 1/6·[[−1, 3, −3, 1], [3, −6, 3, 0], [−3, 0, 3, 0], [1, 4, 1, 0]] za kubne krivulje. Uz stegnute uzlove krajnji segmenti dobivaju vlastite matrice.",
  "matrixForm.try1":
    "Pomičite klizač segmenta: istaknuti dio i njegove obojene točke pomiču se, ali M ostaje ista.",
  "matrixForm.try2":
    "Prebacite na stegnute uzlove i odaberite segment 1: M se mijenja (krivulja mora početi u P₀); uz 6 točaka i p = 2 segmenti 2 i 3 zadržavaju periodičku matricu, kao u primjeru iz bilježaka.",
  "matrixForm.try3":
    "Povucite jednu od zaokruženih točaka i usporedite dva retka tablice rezultata: matrični umnožak i evaluate(u) slažu se na svaku decimalu.",
  "weights.title": "Težine racionalne krivulje",
  "weights.summary":
    "Povećajte težinu i krivulja se privlači prema svojoj kontrolnoj točki; homogena slika pokazuje zašto: polinomna krivulja u (wx, wy, w) projicirana na w = 1.",
  "weights.whatYouSee":
    "Racionalna kubna Bézierova krivulja (plavo) i iste kontrolne točke sa svim težinama 1 (točkasto): prsten oko svake točke raste s njezinom težinom wᵢ, a povećanje wᵢ privlači krivulju prema Pᵢ. Umetak prikazuje homogenu sliku iz grčkih bilježaka (poglavlje 4 nastavnog programa): točke (wᵢxᵢ, wᵢyᵢ, wᵢ) razapinju običnu polinomnu Bézierovu krivulju u prostoru (zeleno), a zrake iz ishodišta projiciraju je na ravninu w = 1, gdje je ona racionalna krivulja. Množenje svih težina istim brojem pomiče zelenu krivulju duž zraka, ali ne i njezinu projekciju: važni su samo omjeri težina.",
  "weights.try1":
    "Povucite klizač w₁ (ili prsten oko P₁) od 0,1 do 10 i gledajte kako P(1/2) klizi prema P₁; zadnji stupac tablice pokazuje kako se udaljenost smanjuje.",
  "weights.try2": "Pritisnite „Sve težine × 2”: zelena krivulja u umetku se pomiče, plava ne.",
  "weights.try3":
    "Pritisnite „Sve težine 1”: racionalna krivulja pada na točkastu polinomnu krivulju.",
  "weights.handleLabel": "P{i} (w{i} = {w})",
  "weights.countMismatch":
    "polje „weights” mora imati jednu težinu po točki: težine {count}, točke {points}",
  "weights.notPositive": "polje „weights”: {name} = {value} je odbijeno; težine moraju biti > 0",
  "weights.outOfRange": "polje „weights”: {name} mora biti između {min} i {max}, dobiveno {value}",
  "weights.weightsLegend": "Težine (logaritamska skala)",
  "weights.weightLabel": "Težina {name} točke {point}",
  "weights.weightInput": "Težina {name} (broj između 0,1 i 10)",
  "weights.badWeight":
    "težina {name} = „{value}” odbijena: težina mora biti > 0 (ovdje između {min} i {max})",
  "weights.allOne": "Sve težine 1",
  "weights.allOne.title": "Postavite sve težine na 1: polinomna Bézierova krivulja",
  "weights.scaleAll": "Sve težine × {factor}",
  "weights.scaleAll.title": "Pomnožite sve težine istim brojem: krivulja se ne mijenja",
  "weights.cannotScale": "težine se ne mogu sve udvostručiti ili prepoloviti unutar {min} … {max}",
  "weights.scaled":
    "Svaka težina {factor}: plava krivulja ostaje gdje je bila (važni su samo omjeri); homogena krivulja u umetku pomaknula se duž zraka.",
  "weights.showHomogeneous": "Prikaži homogeni prostor (umetak)",
  "weights.maxPoints": "ova demonstracija dopušta najviše {max} kontrolnih točaka",
  "weights.minPoints": "najmanji broj kontrolnih točaka u ovoj demonstraciji je {min}",
  "weights.degree": "Stupanj n = {n} (kontrolne točke: {count})",
  "weights.pointLabel": "P({t})",
  "weights.ghostPointLabel": "t = {t}, sve wᵢ = 1",
  "weights.legendRational": "racionalna krivulja",
  "weights.legendPolynomial": "sve težine 1",
  "weights.insetTitle": "Homogeni prostor (wx, wy, w)",
  "weights.axisX": "wx",
  "weights.axisY": "wy",
  "weights.axisW": "w",
  "weights.origin": "O",
  "weights.plane": "w = 1",
  "weights.readout": "P({t}) = ({x}; {y}); najveća udaljenost od polinomne krivulje: {gap}",
  "weights.tableCaption":
    "Kontrolne točke, težine, homogene točke (wᵢxᵢ, wᵢyᵢ, wᵢ), udio Bᵢ(t)wᵢ / Σ Bⱼ(t)wⱼ svake točke za t = {t} i udaljenost |P(t) − Pᵢ|",
  "weights.column.point": "Pᵢ",
  "weights.column.weight": "wᵢ",
  "weights.column.homogeneous": "Pᵢʷ = (wᵢxᵢ, wᵢyᵢ, wᵢ)",
  "weights.column.share": "udio za t",
  "weights.column.distance": "|P(t) − Pᵢ|",
  "weights.tex.ratios": "važni su samo omjeri: ",
  "weights.tex.same": " daje istu krivulju",
  "weights.aria":
    "Racionalna {kind} Bézierova krivulja s težinama ({weights}) i, točkasto, polinomna krivulja sa svim težinama 1; za t = {t} točka P(t) = ({x}; {y}) (sve težine 1: ({gx}; {gy})), {distance} od najteže točke {heaviest}; umetak: homogene kontrolne točke, njihova polinomna krivulja u (wx, wy, w) i zrake iz ishodišta koje je projiciraju na ravninu w = 1",
  "conics.title": "Konike",
  "conics.summary":
    "Racionalna kvadratna Bézierova krivulja je konika: luk elipse za w₁ < 1, parabola za w₁ = 1, hiperbola iznad; uz jednakokračni trokut i w₁ = sin θ, kružni luk.",
  "conics.whatYouSee":
    "Racionalna kvadratna Bézierova krivulja (plavo) s težinama 1, w₁, 1 i, točkasto, parabola koja je za w₁ = 1. Jezgra imenuje koniku prema faktoru oblika k = w₁²/(w₀w₂): ispod 1 luk elipse, jednako 1 parabola, iznad 1 hiperbola; točka ramena P(1/2) klizi duž pravca od polovišta tetive M do P₁. Kad je trokut jednakokračan i w₁ = sin θ, gdje je θ pola kuta u P₁, luk je točno kružni: pojavljuje se cijela kružnica, iscrtkano, sa središtem. Ovo je dio o konikama iz grčkih bilježaka (poglavlje 4 nastavnog programa).",
  "conics.try1":
    "Upišite 0,5; 1 i 2 u polje w₁: naziv se mijenja iz elipse u parabolu pa u hiperbolu, a redak tablice slijedi.",
  "conics.try2":
    "Pritisnite „Napravi kružni luk”: w₁ postaje sin θ i pojavljuje se iscrtkana kružnica; zatim povucite P₂ i gledajte kako „kružnica!” nestaje.",
  "conics.try3":
    "Povucite w₁ do 5: točka ramena juri prema P₁, a hiperbola prianja uz kontrolni trokut.",
  "conics.w1": "Srednja težina w₁ (logaritamska skala)",
  "conics.w1.input": "Težina w₁ (broj između 0,05 i 5)",
  "conics.badWeight":
    "težina w₁ = „{value}” odbijena: w₁ mora biti > 0 (ovdje između {min} i {max})",
  "conics.makeCircular": "Napravi kružni luk",
  "conics.makeCircular.title":
    "Učinite trokut jednakokračnim (P₂ klizi duž P₁P₂) i postavite w₁ = sin θ, težinu kružnog luka",
  "conics.circleLegend": "Kružni luk",
  "conics.notCircular": "nema kružnog luka za ovaj trokut: {message}",
  "conics.tooFlat": "kružni luk treba w₁ = {w}, ispod najmanje težine ove demonstracije {min}",
  "conics.madeCircular": "w₁ = sin θ = {w}: kružni luk.",
  "conics.kind.ellipse": "elipsa",
  "conics.kind.parabola": "parabola",
  "conics.kind.hyperbola": "hiperbola",
  "conics.article.ellipse": "elipse",
  "conics.article.parabola": "parabole",
  "conics.article.hyperbola": "hiperbole",
  "conics.rule.ellipse": "k = w₁²/(w₀w₂) < 1",
  "conics.rule.parabola": "k = 1 (w₁ = 1: polinomna Bézierova krivulja)",
  "conics.rule.hyperbola": "k > 1",
  "conics.column.kind": "konika",
  "conics.column.rule": "pravilo (w₀ = w₂ = 1)",
  "conics.tableCaption": "Koja konika: odlučuje faktor oblika k (trenutna je istaknuta)",
  "conics.figureCircle": "{kind}: kružnica!",
  "conics.readoutCircle": "{kind}: kružnica!",
  "conics.centre": "O",
  "conics.midpoint": "M",
  "conics.shoulder": "P(1/2)",
  "conics.legendParabola": "w₁ = 1 (parabola)",
  "conics.formula.circularArc": "kružni luk",
  "conics.formula.and": "i",
  "conics.formula.circle": "kružnica!",
  "conics.shape": "w₁ = {w}; faktor oblika k = w₁²/(w₀w₂) = {k} {relation} 1",
  "conics.triangle":
    "|P₀P₁| = {a}, |P₁P₂| = {b} (nije jednakokračan); kut u P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleIsosceles":
    "|P₀P₁| = |P₁P₂| = {a} (jednakokračan); kut u P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleDegenerate": "Dvije se točke podudaraju: nema kuta u P₁.",
  "conics.circleYes":
    "kružnica! polumjer {r}; udaljenost svakog uzorka od središta O razlikuje se od njega najviše za {error}.",
  "conics.circleNo":
    "Još nije kružni: luk treba w₁ = sin θ = {sin} (najveća udaljenost od te kružnice sada: {error}).",
  "conics.circleNeedsIsosceles":
    "Nije kružni: kružni luk treba |P₀P₁| = |P₁P₂| (pritisnite „Napravi kružni luk”).",
  "conics.aria":
    "Racionalna kvadratna Bézierova krivulja s P₀ = {p0}, P₁ = {p1}, P₂ = {p2} i težinama 1; {w}; 1: luk {kind} (faktor oblika {k}){circle}; točka ramena P(1/2) = ({sx}; {sy}); točkasto: parabola uz w₁ = 1",
  "conics.ariaCircle": ", kružni luk polumjera {r} oko ({x}; {y})",
  "nurbsCircle.title": "NURBS kružnice i lukovi",
  "nurbsCircle.summary":
    "Točna kružnica kao NURBS stupnja 2: 9 kontrolnih točaka, težine 1 i √2/2, uzlovi 0; 0; 0; ¼; ¼; ½; ½; ¾; ¾; 1; 1; 1. Lukovi u dijelovima od najviše 90°, elipse kao njihove afine slike.",
  "nurbsCircle.whatYouSee":
    "Kružnica (ili luk, ili elipsa) koju jezgra gradi kao NURBS stupnja 2 (plavo), njezin kontrolni poligon s težinom svake točke i spojevi njezinih dijelova (zeleni prstenovi). Puna kružnica je NURBS s 9 točaka iz nastavnog programa (poglavlje 4, prema grčkim i talijanskim bilješkama): vrhovi kvadrata nose težinu √2/2, uzlovi su 0; 0; 0; ¼; ¼; ½; ½; ¾; ¾; 1; 1; 1. Luk se reže na dijelove od najviše 90° čije su srednje težine cos(Δ/2). Očitanje mjeri koliko je 2000 uzoraka udaljeno od točne kružnice: 0 ili nekoliko 10⁻¹⁶, samo zaokruživanje — nijedna polinomna krivulja to ne može.",
  "nurbsCircle.try1":
    "Postavite središnji kut luka na 200°: luk ima 3 dijela od 66,7° i srednje težine cos 33,3° ≈ 0,835; pogreška polumjera i dalje je oko 1e-16.",
  "nurbsCircle.try2":
    "Označite „Elipsa” i mijenjajte rotaciju: iste težine i uzlovi, rastegnute kontrolne točke — afina slika kružnice.",
  "nurbsCircle.try3": "Povucite središte c: cijela se kružnica pomiče i ostaje točna.",
  "nurbsCircle.notPositive": "polje „{field}” mora biti > 0, dobiveno {value}",
  "nurbsCircle.zeroSweep":
    "polje „sweep” ne smije biti 0 (luk treba središnji kut različit od nule)",
  "nurbsCircle.radius": "Polumjer r",
  "nurbsCircle.radius.input": "Polumjer (broj > 0, najviše 10)",
  "nurbsCircle.rx": "Poluos rx",
  "nurbsCircle.rx.input": "Poluos rx (broj > 0, najviše 10)",
  "nurbsCircle.ry": "Poluos ry",
  "nurbsCircle.ry.input": "Poluos ry (broj > 0, najviše 10)",
  "nurbsCircle.rotation": "Rotacija (stupnjevi)",
  "nurbsCircle.rotation.input": "Rotacija elipse u stupnjevima",
  "nurbsCircle.start": "Početni kut (stupnjevi)",
  "nurbsCircle.start.input": "Početni kut u stupnjevima",
  "nurbsCircle.sweep": "Središnji kut luka (stupnjevi, negativno: u smjeru kazaljke)",
  "nurbsCircle.sweep.input": "Središnji kut luka u stupnjevima, od −360 do 360, ne 0",
  "nurbsCircle.badLength":
    "{field} = „{value}” odbijeno: {field} mora biti > 0 (ovdje između {min} i {max})",
  "nurbsCircle.badAngle": "{field} = „{value}” odbijeno: kut između −{max}° i {max}°",
  "nurbsCircle.ellipseMode": "Elipsa (poluosi i rotacija)",
  "nurbsCircle.circleLegend": "Kružnica",
  "nurbsCircle.ellipseLegend": "Elipsa",
  "nurbsCircle.arcLegend": "Luk",
  "nurbsCircle.resultLegend": "NURBS",
  "nurbsCircle.full": "Puni krug",
  "nurbsCircle.full.title": "Početak 0°, središnji kut 360°: zatvorena krivulja s 9 točaka",
  "nurbsCircle.refused": "biblioteka je odbila: {message}",
  "nurbsCircle.centreLabel": "c",
  "nurbsCircle.radiusLabel": "r = {r}",
  "nurbsCircle.axesLabel": "rx = {rx}; ry = {ry}",
  "nurbsCircle.errorCircle": "pogreška polumjera {error}",
  "nurbsCircle.errorEllipse": "pogreška elipse {error}",
  "nurbsCircle.errorCircleNote":
    "max | |C(u) − c| − r | na {samples} uzoraka (samo zaokruživanje: krivulja je točna)",
  "nurbsCircle.errorEllipseNote":
    "max | (x′/rx)² + (y′/ry)² − 1 | na {samples} uzoraka, x′, y′ duž osi",
  "nurbsCircle.count": "Kontrolne točke: {count}, dijelovi: {pieces} (svaki ≤ 90°)",
  "nurbsCircle.knots": "Uzlovi: {knots}",
  "nurbsCircle.ariaCircle": "kružnica polumjera {r}",
  "nurbsCircle.ariaEllipse": "elipsa s poluosima {rx} i {ry} zakrenuta za {rotation}°",
  "nurbsCircle.ariaFull": "cijela krivulja",
  "nurbsCircle.ariaArc": "luk od {start}°, središnjeg kuta {sweep}°",
  "nurbsCircle.aria":
    "NURBS {shape} oko ({x}; {y}), {arc}: stupanj 2, kontrolne točke ({count}) s težinama {weights}, uzlovi {knots}, dijelovi: {pieces}; izmjerena pogreška {error}",
  "nurbsCircle.tableCaption": "Kontrolne točke ({count}) i njihove težine",
  "nurbsCircle.column.point": "Pᵢ",
  "nurbsCircle.column.weight": "wᵢ",
  "nurbsCircle.formula.circle": "kružnica",
  "nurbsCircle.formula.here": "ovdje",
  "nurbsCircle.formula.pieces.few": "dijela od",
  "nurbsCircle.formula.pieces.one": "dio od",
  "nurbsCircle.formula.pieces.other": "dijelova od",
  "nurbsCircle.formula.middleWeights": "srednje težine",
  "nurbsCircle.formula.samples": "uzoraka",
  "projective.title": "Projektivna invarijantnost",
  "projective.summary":
    "Preslikajte racionalnu krivulju perspektivom: preslikavanje njezinih kontrolnih točaka i težina daje točno preslikanu krivulju; preslikavanje točaka uz stare težine ne daje.",
  "projective.whatYouSee":
    "Lijevo kubna Bézierova krivulja u kvadratu S₀S₁S₂S₃; desno njezina slika pri perspektivnom preslikavanju H koje kvadrat šalje u četverokut Q₀Q₁Q₂Q₃ (povlačite vrhove). Jezgra preslikava homogene kontrolne točke krivulje (wᵢPᵢ, wᵢ) s H, što daje nove točke i nove težine (puna plava); narančaste točkice su uzorci izvorne krivulje preslikani jedan po jedan istim H i leže točno na njoj — racionalne krivulje invarijantne s obzirom na projektivna preslikavanja, kako kažu grčke bilješke (poglavlje 4 nastavnog programa). Iscrtkana krivulja koristi preslikane točke sa starim težinama: promašuje, jer perspektiva mijenja težine.",
  "projective.try1":
    "Povucite Q₂ prema Q₃: perspektiva postaje jača, preslikane težine se razilaze, a iscrtkana krivulja udaljava se od točkica, koje ostaju na punoj krivulji.",
  "projective.try2":
    "Pritisnite „Učini afinim”: četverokut postaje paralelogram, svaka preslikana težina jednaka je staroj, a iscrtkana krivulja pridružuje se ostalima.",
  "projective.try3":
    "Povucite Q₂ preko dijagonale Q₁Q₃: preslikavanje bi postavilo kontrolnu točku iza beskonačno dalekog pravca (težina ≤ 0); biblioteka odbija i ostaje posljednja dobra slika.",
  "projective.notPositive": "polje „weights”: {name} = {value} je odbijeno; težine moraju biti > 0",
  "projective.weightRange":
    "polje „weights”: {name} mora biti između {min} i {max}, dobiveno {value}",
  "projective.degenerate":
    "polje „corners”: četiri vrha ne određuju perspektivno preslikavanje (tri na istom pravcu?)",
  "projective.weightsLegend": "Izvorne težine (logaritamska skala)",
  "projective.weightLabel": "Težina {name} točke {point}",
  "projective.weightInput": "Težina {name} (broj između 0,1 i 10)",
  "projective.badWeight":
    "težina {name} = „{value}” odbijena: težina mora biti > 0 (ovdje između {min} i {max})",
  "projective.affine": "Učini afinim",
  "projective.affine.title":
    "Pomaknite Q₂ tako da četverokut bude paralelogram: afino preslikavanje, težine nepromijenjene",
  "projective.resultLegend": "Provjera invarijantnosti",
  "projective.refused": "biblioteka je odbila ovo preslikavanje: {message}",
  "projective.mappedLabel": "w′{i} = {w}",
  "projective.naiveLabel": "nije invarijantno: težine zanemarene",
  "projective.legendMapped": "curve.projectiveMap(H)",
  "projective.legendPointwise": "H primijenjen na svaki uzorak",
  "projective.legendNaive": "preslikane točke, stare težine",
  "projective.gaps":
    "Puna prema točkicama: najveći razmak {ab} (ista krivulja). Iscrtkana prema punoj: {ac}.",
  "projective.mappedWeights": "Preslikane težine w′ᵢ: {weights}",
  "projective.affineMap": "afinim preslikavanjem",
  "projective.perspectiveMap": "perspektivnim preslikavanjem",
  "projective.tex.affine": "(afino preslikavanje: ",
  "projective.tex.unchanged": ", težine nepromijenjene)",
  "projective.tex.invariant": "(invarijantno)",
  "projective.tex.ignored": "(težine zanemarene)",
  "projective.aria":
    "Kubna Bézierova krivulja u kvadratu [0, 4]² i njezina slika {kind} koje vrhove kvadrata šalje u {corners}: preslikana krivulja ima težine {weights}; izvorni uzorci preslikani jedan po jedan leže na njoj (najveći razmak {ab}); preslikane točke sa starim težinama daju drugačiju krivulju (udaljenu do {ac})",
  "negativeWeights.title": "Zašto se nepozitivne težine odbijaju",
  "negativeWeights.summary":
    "Povucite težinu kroz nulu: biblioteka odbija, a demonstracija pokazuje što bi krivulja učinila — napustila konveksnu ljusku i pobjegla u beskonačnost ondje gdje nazivnik w(t) iščezava.",
  "negativeWeights.whatYouSee":
    "Racionalna kvadratna Bézierova krivulja s težinama 1, w₁, 1 nad svojim kontrolnim trokutom (konveksna ljuska, osjenčano). Dok je w₁ > 0, biblioteka gradi krivulju (plavo) i ona ostaje u trokutu. Za w₁ ≤ 0 biblioteka odbija, a njezina se poruka prikazuje doslovno; iscrtkana krivulja je ono što bi dala formula: homogena krivulja (wx, wy, w) i dalje je obična polinomna krivulja, a dijeljenje s w projicira je natrag. Ispod je nazivnik w(t) = Σ Bᵢ(t)wᵢ: gdje prolazi kroz nulu, točka bježi u beskonačnost (pol), a svaka negativna težina već izbacuje krivulju iz njezine konveksne ljuske. To je upozorenje iz grčkih bilježaka (poglavlje 4 nastavnog programa): negativne težine narušavaju svojstvo konveksne ljuske i mogu stvoriti polove.",
  "negativeWeights.try1":
    "Pritisnite „w₁ = −0,5”: biblioteka odbija, krivulja se izvrće ispod tetive P₀P₂ i napušta trokut, ali w(t) ostaje iznad 0 — još nema pola.",
  "negativeWeights.try2":
    "Polako povucite w₁ od 0 do −3: za w₁ = −1 graf dodiruje nulu u t = 1/2, ispod toga siječe je dvaput, i krivulja se kida u dvama polovima.",
  "negativeWeights.try3": "Pritisnite „w₁ = 1”: poruka nestaje i vraća se obična parabola.",
  "negativeWeights.w1": "Srednja težina w₁ (ovdje smije biti ≤ 0)",
  "negativeWeights.w1.input": "Težina w₁ (broj između −3 i 3)",
  "negativeWeights.badWeight":
    "težina w₁ = „{value}” odbijena: ova demonstracija prima w₁ između {min} i {max}",
  "negativeWeights.preset": "w₁ = {w}",
  "negativeWeights.libraryLegend": "Što kaže biblioteka",
  "negativeWeights.resultLegend": "Što bi dala formula",
  "negativeWeights.refused": "biblioteka odbija težine 1, w₁, 1: {message}",
  "negativeWeights.accepted": "Biblioteka prihvaća ove težine.",
  "negativeWeights.libraryRefuses": "new BezierCurve(points, 2, weights) baca iznimku: „{message}”",
  "negativeWeights.libraryAccepts":
    "new BezierCurve(points, 2, weights) prihvaća ove težine: svaki wᵢ > 0.",
  "negativeWeights.poles.few": "{count} pola, za t ≈ {list}",
  "negativeWeights.poles.one": "{count} pol, za t ≈ {list}",
  "negativeWeights.poles.other": "{count} polova, za t ≈ {list}",
  "negativeWeights.noPoles": "nema pola: w(t) > 0 na [0, 1]",
  "negativeWeights.outside": "Krivulja napušta svoju konveksnu ljusku (kontrolni trokut).",
  "negativeWeights.inside": "Krivulja ostaje u svojoj konveksnoj ljusci (kontrolni trokut).",
  "negativeWeights.poleLabel": "pol t ≈ {t}",
  "negativeWeights.infinity": "∞",
  "negativeWeights.middleLabel": "P(1/2)",
  "negativeWeights.figureAccepted": "težine > 0: krivulja biblioteke",
  "negativeWeights.figureRefused": "biblioteka odbija (iscrtkano: formula)",
  "negativeWeights.tickHalf": "1/2",
  "negativeWeights.axisT": "t",
  "negativeWeights.plotTitle": "nazivnik w(t) = Σ Bᵢ(t) wᵢ",
  "negativeWeights.tex.poles": "(polovi)",
  "negativeWeights.tex.noPole": "(nema pola; ",
  "negativeWeights.tex.needs": " treba ",
  "negativeWeights.tex.coefficients": "koeficijenti ",
  "negativeWeights.tex.sumToOne": " imaju zbroj 1: ",
  "negativeWeights.tex.staysInHull": " ostaje u konveksnoj ljusci; ",
  "negativeWeights.tex.breaks": " to narušava",
  "negativeWeights.aria":
    "Racionalna kvadratna Bézierova krivulja s P₀ = {p0}, P₁ = {p1}, P₂ = {p2} i težinama 1; {w}; 1: {verdict}; {poles}; {hull}; ispod, graf nazivnika w(t)",
  "negativeWeights.ariaRefused":
    "biblioteka je odbija ({message}), iscrtkana krivulja je projekcija homogene krivulje prema formuli",
  "negativeWeights.ariaAccepted": "biblioteka je prihvaća",
  "negativeWeights.ariaPoles":
    "w(t) doseže nulu za t ≈ {list} (ukupno {count}): polovi, gdje krivulja bježi u beskonačnost",
  "negativeWeights.ariaNoPoles": "w(t) ostaje pozitivan (najmanja vrijednost {min})",
  "negativeWeights.ariaOutside": "krivulja napušta svoju konveksnu ljusku",
  "negativeWeights.ariaInside": "krivulja ostaje u svojoj konveksnoj ljusci",
  "lagrange.title": "Lagrangeova interpolacija i Aitkenov trokut",
  "lagrange.summary":
    "Jedan polinom kroz sve točke nasuprot kubnom splajnu; Aitkenov trokut gradi P(t) i napušta konveksnu ljusku; vijuganje raste s brojem točaka.",
  "lagrange.aria":
    "Lagrangeov polinom stupnja {n} kroz zadane točke (broj: {count}) uz {params} parametre i prirodni kubni splajn kroz iste točke; t = {t}; P(t) = ({x}; {y}); splajn za t: ({sx}; {sy})",
  "lagrange.error.t": "polje „t”: {t} je izvan domene parametra [{a}; {b}] ovih točaka",
  "lagrange.control.t": "Parametar t",
  "lagrange.control.t.input": "vrijednost t (decimalni broj ili razlomak poput 3/2)",
  "lagrange.control.stepBack.title": "t − 1/16 domene",
  "lagrange.control.step.title": "t + 1/16 domene",
  "lagrange.control.params": "Parametri tᵢ zadanih točaka",
  "lagrange.params.uniform": "uniformni: tᵢ = i",
  "lagrange.params.chord": "duljina tetiva: zbrojevi |pᵢ₊₁ − pᵢ|",
  "lagrange.params.centripetal": "centripetalni: zbrojevi √|pᵢ₊₁ − pᵢ|",
  "lagrange.paramsName.uniform": "uniformne",
  "lagrange.paramsName.chord": "tetivne",
  "lagrange.paramsName.centripetal": "centripetalne",
  "lagrange.control.runge": "Rungeov primjer",
  "lagrange.control.count": "Jednoliko razmaknute točke na Rungeovu zvonu",
  "lagrange.control.count.input": "broj točaka (od {min} do {max})",
  "lagrange.countRange": "broj točaka mora biti cijeli broj od {min} do {max}, dobiveno „{value}”",
  "lagrange.degree.few": "{count} točke: polinom stupnja n = {n}",
  "lagrange.degree.one": "{count} točka: stupanj n = {n}",
  "lagrange.degree.other": "{count} točaka: polinom stupnja n = {n}",
  "lagrange.minPoints": "najmanji broj točaka za Lagrangeovu interpolaciju ovdje je {min}",
  "lagrange.maxPoints": "ova demonstracija dopušta najviše {max} točaka",
  "lagrange.legendPolynomial": "Lagrangeov polinom P(t)",
  "lagrange.legendSpline": "prirodni kubni splajn S(t)",
  "lagrange.pointLabel": "P(t)",
  "lagrange.axisT": "t",
  "lagrange.marker": "t = {t}",
  "lagrange.sumNote": "Σ Lᵢ(t) = {sum}; ovdje je svaki Lᵢ(t) ≥ 0",
  "lagrange.sumNegative":
    "Σ Lᵢ(t) = {sum}, ali L{i}(t) = {value} < 0: P(t) nije konveksna kombinacija točaka",
  "lagrange.colFunction": "Bazna funkcija",
  "lagrange.colParam": "tᵢ",
  "lagrange.colValue": "Lᵢ(t)",
  "lagrange.colPoint": "Zadana točka pᵢ",
  "lagrange.sumRow": "Zbroj",
  "lagrange.basisCaption": "Lagrangeova baza za t = {t}: težina svake zadane točke u P(t)",
  "lagrange.triangleCaption": "Aitkenov trokut za t = {t}: redak r sadrži točke razine r",
  "lagrange.tableLevel": "r = {r}",
  "lagrange.whatYouSee":
    "Plava krivulja je jedini polinom P(t) stupnja n kroz svih n + 1 zadanih točaka; zelena krivulja je prirodni kubni splajn kroz iste točke uz iste parametre. Obojene razine čine Aitkenov trokut za t: svaka nova točka dijeli pravac svoje stranice u omjeru parametara, kao kod de Casteljaua, ali pada izvan stranice (točkasto) kad je t izvan raspona parametara te stranice, a bazne funkcije Lᵢ(t) ispod slike imaju zbroj 1, ali postaju negativne. Iz dijela o interpolaciji grčkih bilježaka, poglavlje 5 nastavnog programa.",
  "lagrange.try1":
    "Pomičite „Jednoliko razmaknute točke na Rungeovu zvonu” od 5 do 11: polinom sve jače oscilira blizu krajeva, a splajn ostaje na zvonu.",
  "lagrange.try2":
    "Pritisnite Pokreni i promatrajte P(t) i njegov trokut: između parametara zadanih točaka točke razine ostaju blizu svojih stranica, a blizu krajeva prelijeću ih.",
  "lagrange.try3":
    "Povucite p₂ prema gore: pomiče se cijeli polinom, čak i daleko od p₂, dok se splajn pomiče uglavnom blizu p₂. Zatim odaberite parametre po duljini tetiva i usporedite.",
  "bezierPatch.title": "Bézierova krpica",
  "bezierPatch.summary":
    "Bikubična krpica sa svojom kontrolnom mrežom 4 × 4: generatrisa koja klizi duž četiriju direktrisa, izokrivulje, normala u ispitnoj točki, matrični oblik.",
  "bezierPatch.aria":
    "Bikubična Bézierova krpica s kontrolnom mrežom 4 × 4; ispitna točka za u = {u}; v = {v}; S(u, v) = ({x}; {y}; {z}); normala ({nx}; {ny}; {nz})",
  "bezierPatch.control.u": "Ispitni u",
  "bezierPatch.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 1/3)",
  "bezierPatch.control.v": "Ispitni v i generatrisa",
  "bezierPatch.control.v.input": "vrijednost v (decimalni broj ili razlomak poput 1/3)",
  "bezierPatch.control.stepBack.title": "v − 1/16",
  "bezierPatch.control.step.title": "v + 1/16",
  "bezierPatch.control.show": "Prikaži",
  "bezierPatch.control.net": "Kontrolna mreža",
  "bezierPatch.control.iso": "Izokrivulje",
  "bezierPatch.control.wireframe": "Žičani model",
  "bezierPatch.control.sweep": "Generatrisa i direktrise",
  "bezierPatch.control.normal": "Normala u ispitnoj točki",
  "bezierPatch.control.shading": "Sjenčanje",
  "bezierPatch.shading.lit": "Osvijetljeno",
  "bezierPatch.shading.zebra": "Zebra-pruge",
  "bezierPatch.shading.gaussian": "Gaussova zakrivljenost K",
  "bezierPatch.shading.mean": "Srednja zakrivljenost H",
  "bezierPatch.normalLabel": "n",
  "bezierPatch.texGeneratrix":
    "\\text{generatrisa za } v = {v}\\text{: kontrolne točke } D_i(v) = [v^3\\ v^2\\ v\\ 1]\\,M\\,[P_{i0}\\ P_{i1}\\ P_{i2}\\ P_{i3}]^T",
  "bezierPatch.whatYouSee":
    "Bikubična Bézierova krpica S(u, v) = Σ Σ B_i(u) B_j(v) P_ij nad svojom kontrolnom mrežom 4 × 4 (sivo, iscrtkano), osvijetljena prema normalama koje računa jezgra. Kao u hrvatskim bilješkama (poglavlje 6), svaki redak mreže određuje direktrisu D_i(v) (zeleno); za dani v njihove točke D_0(v) … D_3(v) kontrolne su točke generatrise (crveno-narančasto), kubne krivulje po u koja opisuje površinu dok v teče. Samo prva i zadnja direktrisa leže na krpici. Strelica je jedinična normala u ispitnoj točki S(u, v). Matrični oblik zapisuje krpicu kao [u³ u² u 1] A [v³ v² v 1]ᵀ uz A = M P Mᵀ, jedna matrica 4 × 4 po koordinati, koju jezgra računa iz trenutne mreže. Zebra-pruge odražavaju paralelne svjetlosne pojaseve na površini; sjenčanja zakrivljenosti boje svaku točku prema K ili H, plavo negativno, bijelo nula, crveno-narančasto pozitivno, skalirano prema najvećoj vrijednosti na krpici (krajevi legende).",
  "bezierPatch.try1":
    "Pritisnite Pokreni pokraj v i gledajte kako generatrisa prelazi krpicu dok njezine kontrolne točke klize duž direktrisa.",
  "bezierPatch.try2":
    "Povucite unutarnju kontrolnu točku poput P₁₁ (ili je odaberite i pritisnite PageUp): površina je slijedi, ali je nikad ne dosegne; povucite kut i krpica prolazi kroz njega.",
  "bezierPatch.try3":
    "Okrećite sliku (povucite prazan prostor) dok ne gledate duž ruba mreže: rubna krivulja je Bézierova krivulja četiriju točaka tog ruba.",
  "bezierPatch.try4":
    "Odaberite Gaussovu zakrivljenost: plava su područja sedlasta (K < 0), crveno-narančasta kupolasta (K > 0). Povlačite P₂₂ gore-dolje i gledajte kako se boje pomiču s izbočinom; prebacite na zebra-pruge i pogledajte kako se savijaju gdje se savija površina.",
  "bezierPatch.try5":
    "Povucite kontrolnu točku samo po jednoj koordinati (odaberite je, koristite strelice) i gledajte koje se od A_x, A_y, A_z mijenjaju: matrični oblik linearan je u mreži, koordinatu po koordinatu.",
  "nurbsSurface.title": "B-površine i NURBS površine",
  "nurbsSurface.summary":
    "Tenzorska B-površina sa stupnjem i uzlovima za svaki smjer: umetanje uzla dodaje cijeli redak ili stupac kontrolnih točaka, težine privlače površinu, šavovi obojeni prema izmjerenom kontinuitetu.",
  "nurbsSurface.aria":
    "B-površina s kontrolnom mrežom {rows} × {cols}, stupnjevi {p} po u i {q} po v; ispitna točka za u = {u}; v = {v}: S = ({x}; {y}; {z}); {seams}",
  "nurbsSurface.control.u": "Ispitni u",
  "nurbsSurface.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 1/3)",
  "nurbsSurface.control.v": "Ispitni v",
  "nurbsSurface.control.v.input": "vrijednost v (decimalni broj ili razlomak poput 1/3)",
  "nurbsSurface.control.directionU": "Smjer u (retci mreže)",
  "nurbsSurface.control.directionV": "Smjer v (stupci mreže)",
  "nurbsSurface.degree1": "1",
  "nurbsSurface.degree2": "2",
  "nurbsSurface.degree3": "3",
  "nurbsSurface.degree4": "4",
  "nurbsSurface.control.knotsU": "Uzlovi U",
  "nurbsSurface.control.knotsV": "Uzlovi V",
  "nurbsSurface.knotsHelp":
    "Broj uzlova: {count} (kontrolne točke: {n}, stupanj {p}); upišite vektor i pritisnite Enter",
  "nurbsSurface.control.insertU": "Umetni uzao po u kod ispitne točke (dodaje redak)",
  "nurbsSurface.control.insertV": "Umetni uzao po v kod ispitne točke (dodaje stupac)",
  "nurbsSurface.control.clamped": "Stegnuti uniformni",
  "nurbsSurface.control.uniform": "Uniformni (nestegnuti)",
  "nurbsSurface.control.weights": "Težina odabrane točke (odaberite hvatište)",
  "nurbsSurface.control.weight": "Težina točke {name}",
  "nurbsSurface.control.weight.input": "težina odabrane kontrolne točke",
  "nurbsSurface.control.show": "Prikaži",
  "nurbsSurface.control.net": "Kontrolna mreža",
  "nurbsSurface.control.iso": "Izokrivulje",
  "nurbsSurface.control.seams": "Šavovi prema kontinuitetu",
  "nurbsSurface.control.normal": "Normala u ispitnoj točki",
  "nurbsSurface.control.shading": "Sjenčanje",
  "nurbsSurface.shading.lit": "Osvijetljeno",
  "nurbsSurface.shading.zebra": "Zebra-pruge",
  "nurbsSurface.shading.gaussian": "Gaussova zakrivljenost K",
  "nurbsSurface.shading.mean": "Srednja zakrivljenost H",
  "nurbsSurface.badWeight": "težina „{value}” mora biti broj u [{min}; {max}]",
  "nurbsSurface.badSelected":
    "polje „selected”: točka {i} ne postoji u mreži s ukupno {count} točaka",
  "nurbsSurface.weightCount": "polje „weights”: težine {count}, kontrolne točke {points}",
  "nurbsSurface.netFull": "ova demonstracija staje na {max} redaka ili stupaca",
  "nurbsSurface.degreeTooHigh":
    "stupanj {p} u smjeru {dir} treba najmanje {p} + 1 kontrolnih točaka u tom smjeru, a mreža ih ima {count}",
  "nurbsSurface.insertedU":
    "Umetnut uzao u = {at}: Boehmovo pravilo na svakom stupcu, mreža je sada {rows} × {cols}",
  "nurbsSurface.insertedV":
    "Umetnut uzao v = {at}: Boehmovo pravilo na svakom retku, mreža je sada {rows} × {cols}",
  "nurbsSurface.noSeams":
    "Nema unutarnjih uzlova: jedna polinomna (ili racionalna) krpica, bez šavova",
  "nurbsSurface.seamsReadout": "Šavovi koje je izmjerila jezgra: {u} · {v}",
  "nurbsSurface.legend": "Šavovi",
  "nurbsSurface.legendFreshRows": "novi retci",
  "nurbsSurface.legendFreshColumns": "novi stupci",
  "nurbsSurface.normalLabel": "n",
  "nurbsSurface.texNet":
    "\\text{mreža } {rows} \\times {cols} = {count} \\text{ točaka},\\ \\text{stupnjevi } p = {p},\\ q = {q}\\text{: šav u uzlu višestrukosti } r \\text{ je } C^{p-r}",
  "nurbsSurface.texInsertedU":
    "\\text{nakon } \\texttt{insertKnotU}\\text{: retci } {first}\\text{–}{last} \\text{ su novi (Boehm na svakom stupcu), jedan redak više}",
  "nurbsSurface.texInsertedV":
    "\\text{nakon } \\texttt{insertKnotV}\\text{: stupci } {first}\\text{–}{last} \\text{ su novi (Boehm na svakom retku), jedan stupac više}",
  "nurbsSurface.whatYouSee":
    "Tenzorska B-površina S(u, v) = Σ Σ N_i,p(u) N_j,q(v) P_ij (s težinama w_ij NURBS površina) nad svojom kontrolnom mrežom (sivo, iscrtkano). Svaki smjer ima vlastiti stupanj i vektor uzlova, a domena je [u_p, u_m+1] × [v_q, v_n+1]. Kako kažu grčke bilješke, uzao se može umetnuti u bilo koji vektor zasebno: umetanje po u primjenjuje Boehmov algoritam na svaki stupac mreže, što dodaje cijeli redak kontrolnih točaka bez promjene površine (retci koje je stvorilo Boehmovo pravilo nacrtani su tamno); po v djeluje na retke i dodaje stupac. Obojene linije su šavovi, izokrivulje u unutarnjim uzlovima, obojene prema kontinuitetu koji jezgra mjeri preko njih (C^(p−r) za uzao višestrukosti r). Pomicanje jedne kontrolne točke mijenja površinu samo na (p + 1) × (q + 1) intervala: lokalni nadzor. Za razliku od krivulja, površine nemaju svojstvo smanjenja varijacije. Izbor sjenčanja prikazuje zebra-pruge (lom u njima je prekid tangentnog kontinuiteta) ili Gaussovu ili srednju zakrivljenost, iz točnih derivacija jezgre.",
  "nurbsSurface.try1":
    "Pritisnite „Umetni uzao po u kod ispitne točke”: pojavljuje se novi redak točaka, a površina ostaje točno gdje je bila; legenda šavova dobiva novi uzao.",
  "nurbsSurface.try2":
    "Upišite 1 u Ispitni u i umetnite: uzao 1 sada je dvostruk, a šav ipak ostaje C², jer umetanje čuva površinu. Sada povucite točku novih redaka: šav pada na C¹, sve što dvostruki uzao jamči uz stupanj 3.",
  "nurbsSurface.try3":
    "Odaberite unutarnje hvatište i povećajte mu težinu: površina se privlači prema njemu, i to samo blizu njega (lokalni nadzor).",
  "nurbsSurface.try4":
    "Povucite kutnu točku, a zatim unutarnju: stegnuta površina prolazi kroz kutove, ali nikad kroz unutarnje točke.",
  "nurbsSurface.try5":
    "Prebacite jedan smjer na uniformne (nestegnute) uzlove: površina se povlači od ruba svoje mreže.",
  "surfaceInterpolation.title": "Interpolacija površine",
  "surfaceInterpolation.summary":
    "B-površina kroz svaku točku mreže 4 × 5: parametri, uzlovi, zatim interpolacija svakog stupca po u i svakog retka rezultata po v.",
  "surfaceInterpolation.aria":
    "B-površina stupnjeva {p} i {q} kroz mrežu {rows} × {cols} zadanih točaka, parametri: {kind}; najveće odstupanje {miss}",
  "surfaceInterpolation.control.parametrisation": "Parametri",
  "surfaceInterpolation.kind.uniform": "Uniformni",
  "surfaceInterpolation.kind.chord": "Duljina tetiva",
  "surfaceInterpolation.kind.centripetal": "Centripetalni",
  "surfaceInterpolation.control.degreeU": "Stupanj p po u",
  "surfaceInterpolation.control.degreeV": "Stupanj q po v",
  "surfaceInterpolation.degree1": "1",
  "surfaceInterpolation.degree2": "2",
  "surfaceInterpolation.degree3": "3",
  "surfaceInterpolation.degree4": "4",
  "surfaceInterpolation.control.show": "Prikaži",
  "surfaceInterpolation.control.columns": "Korak 1: svaki stupac interpoliran po u",
  "surfaceInterpolation.control.net": "Kontrolna mreža rezultata",
  "surfaceInterpolation.control.iso": "Izokrivulje kroz zadane točke",
  "surfaceInterpolation.legendColumns": "korak 1: krivulje stupaca, točke s_il",
  "surfaceInterpolation.legendNet": "kontrolna mreža P_ij",
  "surfaceInterpolation.missReadout":
    "Površina prolazi kroz sve zadane točke ({count}): najveće odstupanje {miss}",
  "surfaceInterpolation.texUnknowns":
    "S(\\bar u_k, \\bar v_l) = Q_{kl},\\ k = 0..{m},\\ l = 0..{n}\\text{: } {rows} \\cdot {cols} = {count} \\text{ jednadžbi za } {count} \\text{ nepoznatih kontrolnih točaka } P_{ij}\\ (p = {p},\\ q = {q})",
  "surfaceInterpolation.texColumns":
    "\\text{1. stupci: } {cols} \\text{ krivulja u } u\\ ({rows} \\times {rows}\\text{, } {cols} \\text{ desnih strana})\\text{: } \\textstyle\\sum_i N_{i,{p}}(\\bar u_k)\\, s_{il} = Q_{kl}",
  "surfaceInterpolation.texRows":
    "\\text{2. retci: } {rows} \\text{ krivulja u } v\\ ({cols} \\times {cols}\\text{, } {rows} \\text{ desnih strana})\\text{: } \\textstyle\\sum_j N_{j,{q}}(\\bar v_l)\\, P_{ij} = s_{il}",
  "surfaceInterpolation.whatYouSee":
    "Mreža od 4 × 5 zadanih točaka Q_kl (hvatišta, visinsko polje) i B-površina kroz svaku od njih. Svaka zadana točka dobiva parametre (ū_k, v̄_l): duž svakog stupca odabrana parametrizacija (uniformna, po duljini tetiva ili centripetalna) normirana na [0, 1], uprosječena po stupcima, i jednako duž redaka; uzlovi su prosjeci parametara. Zatim, kako opisuju grčke bilješke, posao su dva prolaza interpolacije krivulja: najprije se svaki stupac podataka interpolira po u (zelene krivulje i njihove kontrolne točke s_il), zatim se svaki redak tih kontrolnih točaka interpolira po v, što daje kontrolnu mrežu P_ij (ljubičasto, točkasto). Izokrivulja površine za v̄_l upravo je zelena krivulja stupca l. Bikubična inačica iz bilježaka dodaje rubne uvjete (m + 3 kontrolne točke po stupcu); ovdje uprosječeni uzlovi daju jednu kontrolnu točku po zadanoj točki. Interpolacija je globalna: povlačenje jedne zadane točke pomiče cijelu mrežu.",
  "surfaceInterpolation.try1":
    "Uključite izokrivulje: one za v̄_l leže točno na zelenim krivuljama stupaca iz koraka 1, a one za ū_k prolaze kroz retke podataka.",
  "surfaceInterpolation.try2":
    "Povucite najvišu zadanu točku prema gore: površina i dalje prolazi kroz svaku točku, ali se kontrolna mreža pomiče posvuda — nema lokalnog nadzora.",
  "surfaceInterpolation.try3":
    "Prebacujte između uniformnih, tetivnih i centripetalnih parametara nakon što jedan razmak mreže učinite mnogo duljim od ostalih: vijuganja se pomiču.",
  "surfaceInterpolation.try4":
    "Postavite oba stupnja na 1: površina postaje bilinearne krpice kroz mrežu, a kontrolna mreža su sami podaci.",
  "surfaceRevolution.title": "Rotacijske, ekstrudirane i pravčaste površine",
  "surfaceRevolution.summary":
    "Površine načinjene od krivulja: točni NURBS torus, vaza tokarena iz profila koji se može uređivati, profil ekstrudiran duž vektora i pravčasta površina između kvadratne i kubne krivulje.",
  "surfaceRevolution.aria.torus":
    "Torus (R = {R}; r = {r}) opisan rotacijom za {angle}° iz točne NURBS kružnice: racionalna bikvadratna površina s kontrolnom mrežom {rows} × {cols}",
  "surfaceRevolution.aria.vase":
    "Vaza: kubni profil B-krivulje (točke: {count}) u ravnini xz zarotiran za 360° oko osi z; kontrolna mreža {rows} × {cols}",
  "surfaceRevolution.aria.extrude":
    "Kubni profil B-krivulje (točke: {count}) u ravnini xy ekstrudiran duž vektora d; kontrolna mreža {rows} × {cols}",
  "surfaceRevolution.aria.ruled":
    "Pravčasta površina između kvadratne krivulje A i kubne krivulje B, s ravnim izvodnicama; kontrolna mreža {rows} × {cols}",
  "surfaceRevolution.control.mode": "Površina",
  "surfaceRevolution.mode.torus": "Torus (rotacija kružnice)",
  "surfaceRevolution.mode.vase": "Vaza (rotacija profila)",
  "surfaceRevolution.mode.extrude": "Ekstruzija profila",
  "surfaceRevolution.mode.ruled": "Pravčasta površina između dviju krivulja",
  "surfaceRevolution.control.R": "Udaljenost R kružnice od osi",
  "surfaceRevolution.control.R.input": "vrijednost R",
  "surfaceRevolution.control.r": "Polumjer r kružnice",
  "surfaceRevolution.control.r.input": "vrijednost r",
  "surfaceRevolution.control.angle": "Kut rotacije (°)",
  "surfaceRevolution.control.angle.input": "kut u stupnjevima, najviše 360",
  "surfaceRevolution.control.show": "Prikaži",
  "surfaceRevolution.minPoints": "najmanji broj kontrolnih točaka profila je {min}",
  "surfaceRevolution.maxPoints": "profil ovdje prima najviše {max} kontrolnih točaka",
  "surfaceRevolution.control.net": "Kontrolna mreža površine",
  "surfaceRevolution.control.iso": "Izokrivulje",
  "surfaceRevolution.control.wireframe": "Žičani model",
  "surfaceRevolution.check.torus":
    "Mreža {rows} × {cols}. Najveća udaljenost od torusa na mreži uzoraka jezgre: {distance} — točno do zaokruživanja.",
  "surfaceRevolution.check.vase":
    "Mreža {rows} × {cols}. Svaki okvir povlačenja ponovno gradi površinu sa sl.revolve ({revolve} ms) i mrežu trokuta ({mesh} ms).",
  "surfaceRevolution.check.extrude":
    "Mreža {rows} × {cols}. S(u, 1) − S(u, 0) = {d} = d za svaki u.",
  "surfaceRevolution.check.ruled": "Mreža {rows} × {cols}. S(u, ½) = {mid}, polovište A(u) i B(u).",
  "surfaceRevolution.tex.circle":
    "C(v) = (R + r\\cos\\varphi,\\ 0,\\ r\\sin\\varphi),\\ R = {R},\\ r = {r}\\text{: točna NURBS kružnica (9 točaka)}",
  "surfaceRevolution.tex.revolve":
    "S(u, v) = \\mathrm{Rot}_z(u\\,\\theta)\\, C(v),\\ \\theta = {angle}^\\circ\\text{: mreža } {rows} \\times {cols}\\text{, stupanj } 2 \\times 2\\text{ (A8.1)}",
  "surfaceRevolution.tex.weights": "\\text{težine luka } w_{i0} = {weights}",
  "surfaceRevolution.tex.rational":
    "S(u, v) = \\frac{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij} P_{ij}}{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij}},\\quad w_{ij} = w_i\\, w_j",
  "surfaceRevolution.tex.torusCheck":
    "\\max_{{n} \\times {n}\\text{ mreža}} \\Bigl|\\sqrt{\\bigl(\\sqrt{x^2+y^2} - {R}\\bigr)^2 + z^2} - {r}\\Bigr| = {distance}\\text{: točno}",
  "surfaceRevolution.tex.profile":
    "C(v) = \\sum_{j=0}^{{n}} N_{j,3}(v)\\,(x_j,\\ 0,\\ z_j)\\text{: stegnuta kubna}",
  "surfaceRevolution.tex.revolveVase":
    "S(u, v) = \\bigl(x(v)\\cos 2\\pi u,\\ x(v)\\sin 2\\pi u,\\ z(v)\\bigr)\\text{: mreža } {rows} \\times {cols}\\text{ (A8.1)}",
  "surfaceRevolution.tex.vaseNet":
    "P_{ij} = P_j\\text{ zakrenuta za } i \\cdot 45^\\circ\\text{, za neparne } i\\text{ odmaknuta za } \\sqrt2\\ (1/\\cos 45^\\circ)",
  "surfaceRevolution.tex.extrude":
    "S(u, v) = C(u) + v\\,\\mathbf d,\\quad v \\in [0, 1],\\quad \\mathbf d = {d}",
  "surfaceRevolution.tex.extrudeNet":
    "P_{i0} = P_i,\\ P_{i1} = P_i + \\mathbf d\\text{: mreža } {rows} \\times {cols}\\text{, stupanj 3 u } u\\text{, 1 u } v\\text{ (§10.3)}",
  "surfaceRevolution.tex.extrudeCheck": "S({u}, 1) - S({u}, 0) = {d}",
  "surfaceRevolution.tex.ruled":
    "S(u, v) = (1 - v)\\,A(u) + v\\,B(u),\\quad A\\text{ kvadratna},\\ B\\text{ kubna}",
  "surfaceRevolution.tex.ruledNet":
    "\\text{najprije usklađivanje: } A_i' = \\tfrac{i}{3} A_{i-1} + \\bigl(1 - \\tfrac{i}{3}\\bigr) A_i\\text{ (stupanj 2} \\to 3\\text{), mreža } {rows} \\times {cols}\\text{ (§10.3)}",
  "surfaceRevolution.tex.ruledCheck": "A({u}) = {a},\\ B({u}) = {b},\\ S({u}, \\tfrac12) = {mid}",
  "surfaceRevolution.whatYouSee":
    "Površine koje jezgra gradi od krivulja, svaka sa svojom kontrolnom mrežom (sivo, iscrtkano) i izokrivuljama. Rotacija okreće profilnu krivulju oko osi z: svaka kontrolna točka Pⱼ postaje kružnica od 9 kontrolnih točaka (četiri točna kvadratna luka, težine 1, √2/2, 1, …), pa kružni profil daje točno torus, a vaza je točna u svakom smjeru okolo. Ekstruzija pomiče profil duž vektora d: dva stupca, Pᵢ i Pᵢ + d. Pravčasta površina spaja kvadratnu krivulju A i kubnu B ravnim dužinama (izvodnicama): jezgra najprije povećava stupanj A na 3 tako da obje imaju isti stupanj i uzlove.",
  "surfaceRevolution.try1":
    "Torus: smanjite kut na 90° i gledajte kako mreža s 9 redaka prelazi na 3 (jedan luk); uz 180°, 5.",
  "surfaceRevolution.try2":
    "Torus: redak provjere ostaje blizu 10⁻¹⁶ za svaki R, r i kut — racionalna površina je točna, a polinomna bi kružnicu mogla samo aproksimirati.",
  "surfaceRevolution.try3":
    "Vaza: povucite točku profila; pomiče se samo u ravnini xz, a cijela se površina okreće s njom. Odmaknite P₀ od osi da otvorite dno.",
  "surfaceRevolution.try4":
    "Ekstruzija: povucite vrh d strelice da nagnete stijenku; svaka izvodnica ekstruzije kopija je od d.",
  "surfaceRevolution.try5":
    "Pravčasta: usporedite četiri narančaste točkice (prvi stupac mreže) s trima točkama od A — jezgra je povećala stupanj A na kubnu s četiri točke koje crtaju istu krivulju, pa A i B mogu dijeliti jednu mrežu.",
  "patchDeCasteljau.title": "De Casteljau na krpici",
  "patchDeCasteljau.summary":
    "Točka S(u, v) Bézierove krpice izgrađena samo krivuljama: de Casteljau na svakom retku po v, zatim još jednom po u na rezultatima. Redoslijed „najprije stupci” daje istu točku.",
  "patchDeCasteljau.aria":
    "De Casteljauova konstrukcija na Bézierovoj krpici stupnja {degree} × {degree}, {order}, korak {step} od {of}; u = {u}; v = {v}; S(u, v) = ({x}; {y}; {z})",
  "patchDeCasteljau.ariaRows": "najprije retci",
  "patchDeCasteljau.ariaColumns": "najprije stupci",
  "patchDeCasteljau.control.u": "u (trokut stupca)",
  "patchDeCasteljau.control.u.input": "vrijednost u (decimalni broj ili razlomak poput 1/3)",
  "patchDeCasteljau.control.v": "v (trokut svakog retka)",
  "patchDeCasteljau.control.v.input": "vrijednost v (decimalni broj ili razlomak poput 1/3)",
  "patchDeCasteljau.control.stepBackU.title": "u − 1/16",
  "patchDeCasteljau.control.stepU.title": "u + 1/16",
  "patchDeCasteljau.control.stepBackV.title": "v − 1/16",
  "patchDeCasteljau.control.stepV.title": "v + 1/16",
  "patchDeCasteljau.control.order": "Redoslijed",
  "patchDeCasteljau.control.rowsFirst": "Najprije retci (po v, zatim po u)",
  "patchDeCasteljau.control.columnsFirst": "Najprije stupci (po u, zatim po v)",
  "patchDeCasteljau.control.step": "Korak (prikazane razine)",
  "patchDeCasteljau.control.step.input": "korak, cijeli broj",
  "patchDeCasteljau.control.degree": "Stupanj krpice",
  "patchDeCasteljau.degree1": "1 × 1 (bilinearna)",
  "patchDeCasteljau.degree2": "2 × 2 (bikvadratna)",
  "patchDeCasteljau.degree3": "3 × 3 (bikubična)",
  "patchDeCasteljau.degree4": "4 × 4",
  "patchDeCasteljau.control.show": "Prikaži",
  "patchDeCasteljau.control.surface": "Površina",
  "patchDeCasteljau.control.net": "Kontrolna mreža",
  "patchDeCasteljau.pointLabel": "S(u, v)",
  "patchDeCasteljau.step.net": "Korak {k} od {of}: samo kontrolna mreža.",
  "patchDeCasteljau.step.rows":
    "Korak {k} od {of}: razina {r} de Casteljauova trokuta svakog retka za v = {v}.",
  "patchDeCasteljau.step.columns":
    "Korak {k} od {of}: razina {r} de Casteljauova trokuta svakog stupca za u = {u}.",
  "patchDeCasteljau.step.rowResults":
    "Korak {k} od {of}: rezultati redaka Q₀ … (njih {count}) kontrolne su točke izokrivulje za v = {v}.",
  "patchDeCasteljau.step.columnResults":
    "Korak {k} od {of}: rezultati stupaca R₀ … (njih {count}) kontrolne su točke izokrivulje za u = {u}.",
  "patchDeCasteljau.step.column":
    "Korak {k} od {of}: razina {r} de Casteljauova algoritma na Q₀ … za u = {u}.",
  "patchDeCasteljau.step.row":
    "Korak {k} od {of}: razina {r} de Casteljauova algoritma na R₀ … za v = {v}.",
  "patchDeCasteljau.step.point":
    "Korak {k} od {of}: vrh posljednjeg trokuta je točka S(u, v) krpice.",
  "patchDeCasteljau.step.pointColumns":
    "Korak {k} od {of}: vrh posljednjeg trokuta je točka S(u, v) krpice.",
  "patchDeCasteljau.texRows":
    "\\text{svaki redak } i\\text{ za } v = {v}\\text{:}\\ \\ P_{ij}^{r} = (1-v)\\,P_{ij}^{r-1} + v\\,P_{i,j+1}^{r-1},\\quad Q_i = P_{i0}^{{n}}",
  "patchDeCasteljau.texColumn":
    "\\text{zatim za } u = {u}\\text{:}\\ \\ Q_{i}^{r} = (1-u)\\,Q_{i}^{r-1} + u\\,Q_{i+1}^{r-1},\\quad S(u, v) = Q_0^{{m}}",
  "patchDeCasteljau.texColumns":
    "\\text{svaki stupac } j\\text{ za } u = {u}\\text{:}\\ \\ P_{ij}^{r} = (1-u)\\,P_{ij}^{r-1} + u\\,P_{i+1,j}^{r-1},\\quad R_j = P_{0j}^{{m}}",
  "patchDeCasteljau.texRow":
    "\\text{zatim za } v = {v}\\text{:}\\ \\ R_{j}^{r} = (1-v)\\,R_{j}^{r-1} + v\\,R_{j+1}^{r-1},\\quad S(u, v) = R_0^{{n}}",
  "patchDeCasteljau.texBoth":
    "S({u}; {v}) = \\underbrace{{rows}}_{\\text{najprije retci}} = \\underbrace{{columns}}_{\\text{najprije stupci}},\\quad \\lvert\\Delta\\rvert = {gap}",
  "patchDeCasteljau.whatYouSee":
    "Grčke bilješke računaju točku Bézierove površine samo krivuljama. De Casteljauov algoritam izvodi se na svakom retku kontrolne mreže s obzirom na v (boje razina kao u demonstraciji za krivulje); daje m + 1 točaka Q₀ … Qₘ (crveno-narančasto), kontrolne točke izoparametarske krivulje koja pripada v (crveno-narančasta krivulja na krpici). Još jedan de Casteljau na tim točkama, s obzirom na u, završava u točki S(u, v). Redoslijed „najprije stupci” (svaki stupac po u, zatim redak rezultata po v) završava u istoj točki: formula prikazuje oboje.",
  "patchDeCasteljau.try1":
    "Postavite korak na 0 i povećavajte ga jedan po jedan: razine redaka, njihovi rezultati na izokrivulji, zatim posljednji trokut do S(u, v).",
  "patchDeCasteljau.try2":
    "Prebacite na „Najprije stupci”: trokuti se okreću na drugu stranu, a izokrivulja ide poprijeko, no S(u, v) ostaje gdje je bila.",
  "patchDeCasteljau.try3":
    "Pritisnite Pokreni pokraj v: rezultati redaka klize duž Bézierovih krivulja redaka, a njihova izokrivulja prelazi krpicu.",
  "patchDeCasteljau.try4":
    "Povucite unutarnju točku poput P₁₁: mijenja se svaki trokut njezina retka, trokuti ostalih redaka ostaju.",
  "patchDeCasteljau.try5":
    "Odaberite stupanj 1 × 1: jedna razina po smjeru, a S(u, v) je bilinearna interpolacija četiriju kutova.",
  "patchSubdivision.title": "Podjela krpice",
  "patchSubdivision.summary":
    "Bikubična krpica podijeljena u (u₀, v₀) na četiri krpice istog stupnja i adaptivno nacrtana: dijeli se dalje dok svaka mreža nije dovoljno ravna.",
  "patchSubdivision.ariaSplit":
    "Bikubična Bézierova krpica podijeljena u u₀ = {u}; v₀ = {v} na četiri krpice s njihovim mrežama, koje se sastaju u S(u₀, v₀) = ({x}; {y}; {z})",
  "patchSubdivision.ariaAdaptive":
    "Bikubična Bézierova krpica adaptivno teselirana uz toleranciju {tolerance}: {triangles} trokuta; uniformna mreža jednako fina kao najfinija ćelija ima {uniform}",
  "patchSubdivision.control.mode": "Prikaži",
  "patchSubdivision.control.split": "Podjela u (u₀, v₀)",
  "patchSubdivision.control.adaptive": "Adaptivna teselacija",
  "patchSubdivision.control.u0": "u₀",
  "patchSubdivision.control.u0.input": "vrijednost u₀ (decimalni broj ili razlomak poput 1/3)",
  "patchSubdivision.control.v0": "v₀",
  "patchSubdivision.control.v0.input": "vrijednost v₀ (decimalni broj ili razlomak poput 1/3)",
  "patchSubdivision.control.nets": "Četiri kontrolne mreže",
  "patchSubdivision.control.tolerance": "Tolerancija ε (jedinice modela)",
  "patchSubdivision.control.tolerance.input": "tolerancija ε, od {min} do {max}",
  "patchSubdivision.badTolerance":
    "tolerancija ε: „{value}” nije broj od {min} do {max}; zadržava se trenutna vrijednost",
  "patchSubdivision.control.quadtree": "Četverostablo u kvadratu (u, v)",
  "patchSubdivision.splitNote":
    "Četiri bikubične krpice na [0, {u}] × [0, {v}] (narančasto), [0, {u}] × [{v}, 1] (zeleno), [{u}, 1] × [0, {v}] (ljubičasto) i [{u}, 1] × [{v}, 1] (crveno-narančasto).",
  "patchSubdivision.counts":
    "{triangles} trokuta uz ε = {tolerance}; uniformna mreža {n} × {n}, posvuda jednako fina kao najfinija ćelija, ima {uniform}.",
  "patchSubdivision.pointLabel": "S(u₀, v₀)",
  "patchSubdivision.axisU": "u",
  "patchSubdivision.axisV": "v",
  "patchSubdivision.texPieces":
    "\\text{četiri krpice na }[0,u_0]\\times[0,v_0],\\ [0,u_0]\\times[v_0,1],\\ [u_0,1]\\times[0,v_0],\\ [u_0,1]\\times[v_0,1]",
  "patchSubdivision.texPoint": "u_0 = {u},\\ v_0 = {v}\\text{:}\\quad S(u_0, v_0) = {point}",
  "patchSubdivision.texCorner":
    "\\text{zajednički kut: } P^{(1)}_{33} = P^{(2)}_{30} = P^{(3)}_{03} = P^{(4)}_{00} = {corner},\\quad \\max\\lvert P - S(u_0, v_0)\\rvert = {gap}",
  "patchSubdivision.texFlat":
    "\\text{mreža ravna: } 2\\delta + \\tfrac{1}{4}\\lvert D\\rvert \\le \\varepsilon = {tolerance} \\;\\Rightarrow\\; \\text{nacrtaj četverokut kutova, inače podijeli u } (\\tfrac12, \\tfrac12)",
  "patchSubdivision.texCounts":
    "\\text{{triangles} trokuta}\\quad\\text{nasuprot }\\quad 2 \\cdot {n}^2 = {uniform} \\text{ na uniformnoj mreži jednako finoj kao najfinija ćelija}",
  "patchSubdivision.whatYouSee":
    "Grčke bilješke dijele Bézierovu površinu kao krivulju: odaberite par (u₀, v₀); de Casteljau na svakom retku mreže dijeli krivulju svakog retka na „lijevi” i „desni” dio; de Casteljau na stupcima obaju dijelova dijeli svaki na „gornji” i „donji” dio. Rezultat su četiri krpice istog tipa, svaka s vlastitom mrežom (m + 1) × (n + 1) (četiri boje); zajedno čine krpicu i sastaju se u S(u₀, v₀). U načinu „Adaptivna” izvodi se pravilo crtanja iz bilježaka: ako su kontrolne točke (gotovo) komplanarne, nacrtaj četverokut četiriju kutnih točaka, inače podijeli na četiri i ponovi za svaki dio. Ovdje se „gotovo” mjeri prema toleranciji ε (δ omeđuje udaljenost mreže od bilinearne krpice njezinih kutova, D je njezino uvijanje), pa svaka točka svakog trokuta leži unutar ε od površine. Umetak prikazuje ćelije u kvadratu (u, v).",
  "patchSubdivision.try1":
    "Pomičite u₀ i v₀: četiri se mreže mijenjaju, ali njihov zajednički kut uvijek leži na krpici, u S(u₀, v₀).",
  "patchSubdivision.try2":
    "Povucite u₀ na 0: dva se dijela stežu u krivulje (njihove se mreže urušavaju na rub).",
  "patchSubdivision.try3":
    "Prebacite na „Adaptivna teselacija” i smanjite ε: ćelije se dijele gdje se krpica savija, a ostaju velike gdje je gotovo ravna.",
  "patchSubdivision.try4":
    "U adaptivnom načinu povucite izbočinu P₂₂ dolje u ravninu njezinih susjeda: male ćelije oko nje stapaju se u velike.",
  "patchSubdivision.try5":
    "Usporedite broj trokuta s uniformnom mrežom jednako finom kao najfinija ćelija: adaptivna mreža troši trokute samo ondje gdje se krpica savija.",
  "hermite.title": "Kubna Hermiteova interpolacija",
  "hermite.summary":
    "Kubni dio između dviju zadanih točaka iz samih točaka i njihovih tangenti; dijelovi koji dijele tangente spajaju se C¹, otključana tangenta samo G¹.",
  "hermite.aria":
    "Po dijelovima kubna Hermiteova krivulja kroz zadane točke (broj: {count}); t = {t}; P(t) = ({x}; {y}); spojevi: {joints}",
  "hermite.whatYouSee":
    "Plava krivulja prolazi kroz zadane točke P₀ … Pₙ za t = 0, 1, 2, …; u svakoj točki narančasta strelica pokazuje njezinu tangentu m (nacrtanu na pola duljine; povucite joj vrh). Između Pᵢ i Pᵢ₊₁ krivulja je H₀·Pᵢ + H₁·Pᵢ₊₁ + H₂·Δmᵢ + H₃·Δmᵢ₊₁, s četiri Hermiteove bazne funkcije nacrtane ispod (poglavlje 5 nastavnog programa, prema poglavlju o interpolaciji grčkih bilježaka i hrvatskim bilješkama). Dijeljenje jedne tangente po točki čini krivulju C¹; provjera kontinuiteta jezgre imenuje svaki spoj.",
  "hermite.try1":
    "Pritisnite Pokreni i gledajte kako oznaka prelazi H₀ … H₃ ispod: za u = 1/2 tablica pokazuje H₀ = H₁ = 1/2 i H₂ = −H₃ = 1/8.",
  "hermite.try2":
    "Povucite vrh strelice tangente u P₁: mijenjaju se samo dva dijela koja se sastaju u P₁, a spoj ostaje C¹.",
  "hermite.try3":
    "Označite „Otključaj tangentu”, zatim povucite ljubičastu dolaznu strelicu ili promijenite λ: spoj postaje „samo G¹” — isti smjer, različita brzina.",
  "hermite.minPoints": "najmanji broj zadanih točaka za Hermiteovu interpolaciju je {min}",
  "hermite.maxPoints": "ova demonstracija dopušta najviše {max} zadanih točaka",
  "hermite.count": "Zadane točke: {count}, kubni dijelovi: {pieces}",
  "hermite.local": "Dio {i}: u = {u} (Δ = {delta})",
  "hermite.control.tangent": "Tangenta m{i} odabrane točke (x y)",
  "hermite.badTangent": "tangenta su dva broja poput „3 -1/2”, dobiveno „{value}”",
  "hermite.control.bezier": "Prikaži Bézierov oblik trenutnog dijela",
  "hermite.control.joinLegend": "Spojevi",
  "hermite.control.unlocked": "Otključaj tangentu u unutarnjoj točki (G¹)",
  "hermite.control.joint": "Otključana točka k",
  "hermite.control.joint.input": "indeks k otključane točke",
  "hermite.control.ratio": "λ = |m⁻| / |m⁺|",
  "hermite.control.ratio.input": "omjer duljina λ dolazne i odlazne tangente",
  "hermite.joints": "Provjera jezgre u spojevima: {list}",
  "hermite.noJoints": "Jedan dio: nema spoja za provjeru",
  "hermite.g1Only": "samo G¹",
  "hermite.c0Only": "samo C⁰",
  "hermite.marker": "u = {u}",
  "hermite.formula.checker": "provjera jezgre:",
  "hermite.col.function": "Funkcija",
  "hermite.col.polynomial": "Polinom",
  "hermite.col.value": "Vrijednost za u",
  "hermite.col.times": "Množi",
  "hermite.tableCaption": "Hermiteova baza za u = {u} (dio {i})",
  "cardinal.title": "Kardinalni splajnovi i Catmull–Rom",
  "cardinal.summary":
    "Tangente se biraju automatski iz susjednih točaka: napetost c ih skraćuje; Catmull–Romov α (uniformni, centripetalni, tetivni) odlučuje hoće li kratki segment napraviti petlju.",
  "cardinal.aria":
    "Krivulja s tangentama: {mode} ({value}), kroz zadane točke (broj: {count}); {loop}",
  "cardinal.whatYouSee":
    "Hermiteova krivulja kroz zadane točke čije tangente (narančasto, nacrtane kao Bézierova hvatišta Δ·m/3) dolaze od susjednih točaka (poglavlje 5 nastavnog programa; hrvatske bilješke daju matrični oblik Catmull–Roma prikazan u ploči s formulom). U kardinalnom načinu napetost c ih umanjuje; u načinu Catmull–Rom parametarski koraci su |Pᵢ₊₁ − Pᵢ|^α. Točke su nejednoliko razmaknute, pa uniformni Catmull–Rom (α = 0, iscrtkano) čini petlju u kratkom segmentu P₁P₂, a centripetalni (α = ½) ne.",
  "cardinal.try1":
    "Pomaknite α od 0,5 do 0: puna krivulja prelazi u iscrtkanu i pojavljuje se petlja u segmentu 1; uz α = 1 (duljina tetiva) prianja uz poligon.",
  "cardinal.try2":
    "Prebacite na kardinalni i povećajte napetost c prema 1: tangente se smanjuju do nule i krivulja postaje poligon; uz c < 0 krivulja premašuje točke (prebačaj).",
  "cardinal.try3":
    "Odmičite P₂ od P₁ dok segmenti ne budu približno jednako dugi: petlja uniformne krivulje nestaje — šiljci i petlje nastaju zbog nejednolikog razmaka.",
  "cardinal.minPoints": "najmanji broj zadanih točaka u ovoj demonstraciji je {min}",
  "cardinal.maxPoints": "ova demonstracija dopušta najviše {max} zadanih točaka",
  "cardinal.count": "Zadane točke: {count}",
  "cardinal.control.modeLegend": "Tangente",
  "cardinal.mode.cardinal": "kardinalni (napetost c)",
  "cardinal.mode.catmull-rom": "Catmull–Rom (α)",
  "cardinal.control.tension": "Napetost c",
  "cardinal.control.tension.input": "napetost c (od −1 do 1)",
  "cardinal.control.alpha": "α (0 uniformni, ½ centripetalni, 1 tetivni)",
  "cardinal.control.alpha.input": "eksponent α (od 0 do 1)",
  "cardinal.control.closed": "Zatvorena krivulja",
  "cardinal.control.segment": "Segment i (od Pᵢ do Pᵢ₊₁)",
  "cardinal.control.segment.input": "indeks segmenta i",
  "cardinal.loopHere": "Ova krivulja čini petlju unutar segmenta {i}.",
  "cardinal.loopGhost":
    "Uniformna krivulja (α = 0, iscrtkano) čini petlju unutar segmenta {i}; ova ne.",
  "cardinal.noLoopHere": "Nema petlje unutar segmenta.",
  "cardinal.noLoopGhost": "Nema petlje unutar segmenta, čak ni za α = 0.",
  "cardinal.loopLabel": "petlja",
  "cardinal.legend.curve": "ova krivulja",
  "cardinal.legend.ghost": "uniformna, α = 0",
  "cardinal.formula.ghost": "(α = 0: iscrtkana krivulja)",
  "cardinal.col.point": "Točka",
  "cardinal.col.param": "Parametar tᵢ",
  "cardinal.col.tangent": "Tangenta mᵢ (jezgra)",
  "cardinal.tableCaption": "Parametri i tangente u zadanim točkama",
  "cubicSpline.title": "C2 kubni splajnovi: rubni uvjeti",
  "cubicSpline.summary":
    "Prirodni, stegnuti, kvadratni, Besselov, not-a-knot i periodički rubni uvjet na istim točkama: trodijagonalni sustav, C″ i C‴ po dijelovima",
  "cubicSpline.aria":
    "C2 kubni splajn kroz točke (broj: {count}), rubni uvjet: {end}, parametri: {parametrization}; rubne tangente m₀ = {m0}, mₙ = {mn}",
  "cubicSpline.whatYouSee":
    "C2 kubni splajn kroz točke: jedan kubni Hermiteov dio između susjeda, a njegove tangente mᵢ određene su iz trodijagonalnog sustava koji čini C″ neprekinutom u svakoj unutarnjoj točki, uz po jednu jednadžbu na svakom kraju — rubni uvjet. Tablica prikazuje taj sustav s trenutnim brojevima, s istaknutim rubnim retcima; grafovi ispod slike prikazuju C″ (neprekinutu u spojevima) i C‴ (koja u njima skače) dio po dio. Prema kubnoj Hermiteovoj interpolaciji iz grčkih bilježaka (poglavlje 5 nastavnog programa), u kojima su retci prirodnog i kvadratnog uvjeta na dalekom kraju tiskani s pogrešnim faktorima: ovdje su retci izvedeni.",
  "cubicSpline.try1":
    "Odaberite prirodni i pogledajte graf C″: obje su komponente 0 u prvom i posljednjem spoju. Zatim odaberite kvadratni: C‴ je 0 na prvom i posljednjem dijelu (to su parabole), a prvi redak tablice postaje 1, 1 | 2(p₁ − p₀)/Δ₀.",
  "cubicSpline.try2":
    "Odaberite not-a-knot i promatrajte graf C‴: skokovi u t₁ i tₙ₋₁ su nestali, pa su prva dva i posljednja dva dijela svaki po jedna kubna krivulja. Odaberite stegnuti i povucite strelice u P₀ i Pₙ.",
  "cubicSpline.try3":
    "Označite „preklopi svih šest” i povucite točku u sredini: daleko od krajeva šest se krivulja slaže, blizu krajeva razilaze se. Prebacite na parametre po duljini tetiva i povucite točku blizu njezina susjeda.",
  "cubicSpline.minPoints": "najmanji broj točaka splajna ovdje je {min}",
  "cubicSpline.maxPoints": "ova demonstracija dopušta najviše {max} točaka",
  "cubicSpline.pointCount.few": "{count} točke, n = {n}",
  "cubicSpline.pointCount.one": "{count} točka, n = {n}",
  "cubicSpline.pointCount.other": "{count} točaka, n = {n}",
  "cubicSpline.control.end": "Rubni uvjet",
  "cubicSpline.control.compare": "Preklopi svih šest",
  "cubicSpline.control.parametrization": "Parametri tᵢ",
  "cubicSpline.control.third": "Nacrtaj i C‴",
  "cubicSpline.end.natural": "prirodni",
  "cubicSpline.end.clamped": "stegnuti",
  "cubicSpline.end.quadratic": "kvadratni",
  "cubicSpline.end.bessel": "Besselov",
  "cubicSpline.end.not-a-knot": "not-a-knot (bez uzla u t₁)",
  "cubicSpline.end.periodic": "periodički",
  "cubicSpline.parametrization.uniform": "uniformni",
  "cubicSpline.parametrization.chord": "duljina tetiva",
  "cubicSpline.parametrization.centripetal": "centripetalni",
  "cubicSpline.closingLabel": "P₀ = P{n}",
  "cubicSpline.tipStart": "m₀",
  "cubicSpline.tipEnd": "mₙ",
  "cubicSpline.plotNote":
    "C″(t₀) = {secondStart}, C″(t{n}) = {secondEnd}; C‴ = {thirdFirst} na prvom dijelu, {thirdLast} na posljednjem; C‴ skače u {jumps}",
  "cubicSpline.noJumps": "nijednom spoju",
  "cubicSpline.plotX": "x",
  "cubicSpline.plotY": "y",
  "cubicSpline.plotSecond": "C″(t)",
  "cubicSpline.plotThird": "C‴(t)",
  "cubicSpline.tex.params": "parametri:",
  "cubicSpline.tex.given": "zadano",
  "cubicSpline.tex.arrow": "strelica u",
  "cubicSpline.tex.parabola": "parabola kroz",
  "cubicSpline.tex.continuous": "neprekinuto u",
  "cubicSpline.tex.start": "početak",
  "cubicSpline.tex.end": "kraj",
  "cubicSpline.row.interior": "C″ neprekinuta u t{i}",
  "cubicSpline.row.start.natural": "C″(t₀) = 0: 2m₀ + m₁ = 3(p₁ − p₀)/Δ₀",
  "cubicSpline.row.end.natural": "C″(t{n}) = 0: m{a} + 2m{n} = 3(p{n} − p{a})/Δ{a}",
  "cubicSpline.row.start.quadratic": "C″(t₀) = C″(t₁): m₀ + m₁ = 2(p₁ − p₀)/Δ₀",
  "cubicSpline.row.end.quadratic": "C″(t{a}) = C″(t{n}): m{a} + m{n} = 2(p{n} − p{a})/Δ{a}",
  "cubicSpline.row.start.clamped": "m₀ zadan (strelica u P₀)",
  "cubicSpline.row.end.clamped": "m{n} zadan (strelica u P{n})",
  "cubicSpline.row.start.bessel": "m₀ = tangenta parabole kroz p₀, p₁, p₂",
  "cubicSpline.row.end.bessel": "m{n} = tangenta parabole kroz p{c}, p{a}, p{n}",
  "cubicSpline.row.start.not-a-knot": "not-a-knot: C‴ neprekinuta u t₁",
  "cubicSpline.row.end.not-a-knot": "not-a-knot: C‴ neprekinuta u t{a}",
  "cubicSpline.row.start.periodic": "periodički: C″ neprekinuta u t₀ = t{n}",
  "cubicSpline.row.end.periodic": "C″ neprekinuta u t{last}, m{n} = m₀",
  "cubicSpline.systemEquation": "Jednadžba",
  "cubicSpline.systemUnknown": "mᵢ",
  "cubicSpline.systemRhs": "cᵢ",
  "cubicSpline.tableCaption":
    "Trodijagonalni sustav A·m = c (jednadžbi: {size}) za tangente mᵢ = C′(tᵢ), rubni uvjet: {end}, parametri: {parametrization}; rubni retci su istaknuti{hidden}",
  "cubicSpline.tableCaptionCyclic":
    "Ciklički trodijagonalni sustav A·m = c (jednadžbi: {size}) za tangente mᵢ = C′(tᵢ), rubni uvjet: {end}, parametri: {parametrization}; rubni retci su istaknuti, kutovi uokvireni{hidden}",
  "cubicSpline.tableHidden": " (izostavljeni srednji retci i stupci, njih {count}: ⋮, ⋯)",
  "parametrization.title": "Parametrizacija: uniformna, po duljini tetiva, centripetalna",
  "parametrization.summary":
    "Iste točke interpolirane uz uniformne, tetivne i centripetalne parametre, s brzinom i oznakama parametara svake krivulje: nejednolik razmak tjera uniformnu krivulju da premašuje točke.",
  "parametrization.aria":
    "{method} kroz zadane točke (broj: {count}) uz uniformne, tetivne, centripetalne parametre i parametre za α = {alpha}; za s = {s}: uniformna {uniform}, tetivna {chord}, centripetalna {centripetal}; njihove su brzine nacrtane ispod",
  "parametrization.control.s": "Normirani parametar s",
  "parametrization.control.s.input": "vrijednost s od 0 do 1 (decimalni broj ili razlomak)",
  "parametrization.control.alphaGroup": "Četvrta krivulja: tᵢ₊₁ = tᵢ + |pᵢ₊₁ − pᵢ|^α",
  "parametrization.control.alpha": "Eksponent α",
  "parametrization.control.alpha.input": "α od 0 do 1",
  "parametrization.control.alphaCurve": "Prikaži krivulju za α (narančasto, crta-točka)",
  "parametrization.alphaIs.uniform": "α = {alpha}: uniformni parametri (na plavoj krivulji)",
  "parametrization.alphaIs.chord": "α = {alpha}: parametri po duljini tetiva (na zelenoj krivulji)",
  "parametrization.alphaIs.centripetal":
    "α = {alpha}: centripetalni parametri (na ljubičastoj krivulji)",
  "parametrization.alphaBetween":
    "α = {alpha}: 0 je uniformno, 0,5 centripetalno, 1 duljina tetiva",
  "parametrization.control.method": "Interpolacijska krivulja",
  "parametrization.method.cubic": "C² prirodni kubni splajn",
  "parametrization.method.catmull-rom": "Catmull–Rom splajn (C¹)",
  "parametrization.methodName.cubic": "Prirodni kubni splajnovi",
  "parametrization.methodName.catmull-rom": "Catmull–Rom splajnovi",
  "parametrization.minPoints": "najmanji broj točaka interpolacijskog splajna ovdje je {min}",
  "parametrization.maxPoints": "ova demonstracija dopušta najviše {max} točaka",
  "parametrization.legend.uniform": "uniformna (α = 0)",
  "parametrization.legend.chord": "tetivna (α = 1)",
  "parametrization.legend.centripetal": "centripetalna (α = ½)",
  "parametrization.legend.alpha": "α s klizača",
  "parametrization.marker": "s = {s}",
  "parametrization.axisSpeed": "brzina |dC/ds|",
  "parametrization.axisS": "s = (t − t₀)/(tₙ − t₀)",
  "parametrization.tex.uniform": "uniformna",
  "parametrization.tex.chord": "tetivna",
  "parametrization.tex.centripetal": "centripetalna",
  "parametrization.tableCaption": "Stranice poligona podataka i parametri tᵢ svake parametrizacije",
  "parametrization.colKind": "i",
  "parametrization.rowLegs": "|pᵢ₊₁ − pᵢ|",
  "parametrization.row.uniform": "uniformni tᵢ",
  "parametrization.row.chord": "tetivni tᵢ",
  "parametrization.row.centripetal": "centripetalni tᵢ",
  "parametrization.row.alpha": "α = {alpha}: tᵢ",
  "parametrization.whatYouSee":
    "Četiri interpolacijske krivulje kroz iste točke, koje se razlikuju samo po parametrima tᵢ pridijeljenima točkama: uniformni (plavo, puna linija), po duljini tetiva (zeleno, iscrtkano), centripetalni (ljubičasto, točkasto) i bilo koji α s klizača (narančasto, crta-točka). Ispod slike je brzina svake krivulje u ovisnosti o normiranom parametru s te za svaku krivulju red oznaka gdje padaju parametri njezinih zadanih točaka. Uniformni parametri dugoj stranici daju jednako malo parametra kao kratkoj, pa krivulja juri duž duge stranice i premašuje točke ili čini petlje na kratkima. Iz dijela o interpolaciji grčkih bilježaka, poglavlje 5 nastavnog programa.",
  "parametrization.try1":
    "Pritisnite Pokreni: četiri točkice počinju i završavaju zajedno, ali plava (uniformna) juri duž dugih stranica dok zelena (tetivna) drži gotovo jednoliki tempo — usporedite njihove grafove brzine.",
  "parametrization.try2":
    "Pomičite α od 0 do 1: narančasta krivulja prolazi kroz plavu (α = 0), ljubičastu (α = 0,5) i zelenu (α = 1), a njezine se oznake pomiču s njom.",
  "parametrization.try3":
    "Povucite p₃ blizu p₂ tako da jedna stranica bude vrlo kratka: uniformna krivulja ondje čini petlju, centripetalna ne. Zatim prebacite na Catmull–Rom i učinite isto.",
  "bsplineInterpolation.title": "Interpolacija B-krivuljom",
  "bsplineInterpolation.summary":
    "B-krivulja bilo kojeg stupnja kroz zadane točke, s neobaveznim derivacijama na krajevima: kontrolne točke rješavaju kvadratni linearni sustav, prikazan s brojevima.",
  "bsplineInterpolation.aria":
    "{kind} B-krivulja kroz zadane točke (broj: {count}), parametri: {params}, {ends}; broj nepoznanica (kontrolnih točaka r): {size}; uzlovi {knots}",
  "bsplineInterpolation.aria.start": "zadana početna derivacija D₀",
  "bsplineInterpolation.aria.end": "zadana završna derivacija",
  "bsplineInterpolation.aria.noEnds": "bez derivacija na krajevima",
  "bsplineInterpolation.degreeLegend": "Stupanj p",
  "bsplineInterpolation.degreeOption": "{p}",
  "bsplineInterpolation.minPoints":
    "stupanj {degree} treba najmanje ovoliko uvjeta (zadane točke i derivacije na krajevima zajedno): {min}",
  "bsplineInterpolation.error.degree":
    "polje „degree” je {p}, ali uz uvjete ({count}: zadane točke i derivacije na krajevima) najveći je stupanj {max}",
  "bsplineInterpolation.maxPoints": "ova demonstracija dopušta najviše {max} zadanih točaka",
  "bsplineInterpolation.paramsLegend": "Parametri tᵢ",
  "bsplineInterpolation.params.uniform": "uniformni",
  "bsplineInterpolation.params.chord": "duljina tetiva",
  "bsplineInterpolation.params.centripetal": "centripetalni",
  "bsplineInterpolation.paramsNote": "t = {list}",
  "bsplineInterpolation.derivativesLegend": "Derivacije na krajevima (povucite vrhove strelica)",
  "bsplineInterpolation.control.start": "Početak: C′(t₀) = D₀",
  "bsplineInterpolation.control.end": "Kraj: C′(tₙ) = Dₙ",
  "bsplineInterpolation.startValue": "D₀ = {xy}",
  "bsplineInterpolation.endValue": "D{n} = {xy}",
  "bsplineInterpolation.noDerivatives": "nema uvjeta na derivacije: samo jedan po zadanoj točki",
  "bsplineInterpolation.legendCurve": "C(u), kroz zadane točke pᵢ",
  "bsplineInterpolation.legendPolygon": "kontrolni poligon rⱼ (izračunat)",
  "bsplineInterpolation.legendDerivative": "derivacija na kraju D = C′(t), puna duljina",
  "bsplineInterpolation.startLabel": "D₀",
  "bsplineInterpolation.endLabel": "Dₙ",
  "bsplineInterpolation.control.notesKnots": "Uzlovi iz bilježaka 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.knotsNotes": "Uzlovi U = {list} (izbor iz bilježaka)",
  "bsplineInterpolation.knotsDefault": "Uzlovi U = {list} (zadano u jezgri: uprosječeni parametri)",
  "bsplineInterpolation.sizeNote": "{points} i derivacije daju {unknowns}",
  "bsplineInterpolation.dataPoints.few": "{count} zadane točke",
  "bsplineInterpolation.dataPoints.one": "{count} zadana točka",
  "bsplineInterpolation.dataPoints.other": "{count} zadanih točaka",
  "bsplineInterpolation.controlPoints.few": "{count} kontrolne točke",
  "bsplineInterpolation.controlPoints.one": "{count} kontrolna točka",
  "bsplineInterpolation.controlPoints.other": "{count} kontrolnih točaka",
  "bsplineInterpolation.notesExample": "Hrvatski primjer",
  "bsplineInterpolation.notesExample.title":
    "Natrag na riješeni primjer iz bilježaka: njegovih 5 točaka, t = 0 … 4, p = 2, početna derivacija i uzlovi 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.row.point": "C({t}) = p{i}",
  "bsplineInterpolation.row.start": "C′({t}) = D₀",
  "bsplineInterpolation.row.end": "C′({t}) = D{i}",
  "bsplineInterpolation.col.condition": "Uvjet",
  "bsplineInterpolation.col.unknown": "Nepoznanica",
  "bsplineInterpolation.col.rhs": "Desna strana",
  "bsplineInterpolation.col.solution": "Rješenje",
  "bsplineInterpolation.tableCaption":
    "Sustav A r = b iz bsplineInterpolationSystem ({size} × {size}): redak i je uvjet, stupac j težina od rⱼ u njemu (Nⱼ,ₚ(tᵢ) ili N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableCaptionNotes":
    "Sustav A r = b iz bilježaka, {size} × {size} (bsplineInterpolationSystem): redak i je uvjet, stupac j težina od rⱼ u njemu (Nⱼ,ₚ(tᵢ) ili N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableTooLarge":
    "Broj nepoznanica sustava: {size}; tablica prikazuje sustave do {max}. Uklonite točke ili smanjite stupanj da ga vidite.",
  "bsplineInterpolation.whatYouSee":
    "Krivulja prolazi kroz zadane točke pᵢ (okrugla hvatišta) za parametre tᵢ; to je B-krivulja čije kontrolne točke rⱼ (sivi kvadratići i iscrtkani poligon) nisu zadane nego izračunate: svaka zadana točka i svaka derivacija na kraju Dᵢ (strelice, puna duljina, derivacija po t) jedna je linearna jednadžba u rⱼ, a tablica ispod slike je taj kvadratni sustav s rješenjem. Početno je riješeni primjer iz hrvatskih bilježaka (poglavlje 5 nastavnog programa): pet točaka za t = 0 … 4, kvadratna krivulja, početna derivacija i uzlovi 0 0 0 1 2 3 4 4 4, što daje sustav 6 × 6 s retcima 1; −2 2; ½ ½ … .",
  "bsplineInterpolation.try1":
    "U primjeru pročitajte drugi redak: −2 r₀ + 2 r₁ = D₀, pa je r₁ = p₀ + D₀/2 — sivi kvadratić r₁ leži na pola strelice. Povucite vrh strelice i gledajte kako ga r₁ slijedi.",
  "bsplineInterpolation.try2":
    "Povećavajte stupanj korak po korak: krivulja i dalje prolazi kroz svaku točku, ali retci postaju dulji (svaki uvjet uključuje p + 1 kontrolnih točaka), a kontrolni poligon izlazi sve dalje.",
  "bsplineInterpolation.try3":
    "Odvucite p₂ daleko udesno: uz uniformne parametre krivulja daleko premašuje p₂ i p₃. Prebacite na duljinu tetiva: tᵢ sada rastu sa stranicama i otklon se smanjuje — ali D₀, derivacija po t, sada je prebrza za parametar koji broji duljinu: skratite strelicu i kuka u p₀ nestaje.",
  "interpolateApproximate.title": "Interpolirati ili aproksimirati",
  "interpolateApproximate.summary":
    "Iste točke kao kontrolne točke (krivulja se privlači prema njima), kao podaci kroz koje se točno prolazi ili kao podaci aproksimirani s manje kontrolnih točaka metodom najmanjih kvadrata.",
  "interpolateApproximate.aria.control":
    "{kind} B-krivulja sa zadanim točkama (broj: {count}) kao kontrolnim točkama (stegnuti uzlovi): prolazi samo kroz prvu i posljednju",
  "interpolateApproximate.aria.data":
    "{kind} B-krivulja prilagođena zadanim točkama (broj: {count}) s {control} ({fit}); najveći ostatak {max}",
  "interpolateApproximate.aria.interpolation": "interpolacija",
  "interpolateApproximate.aria.leastSquares": "najmanji kvadrati, krajevi točni",
  "interpolateApproximate.roleLegend": "Točke su",
  "interpolateApproximate.role.control": "kontrolne točke (aproksimacija)",
  "interpolateApproximate.role.data": "zadane točke (interpolacija ili prilagodba)",
  "interpolateApproximate.degreeLegend": "Stupanj p",
  "interpolateApproximate.degreeOption": "{p}",
  "interpolateApproximate.minPoints":
    "B-krivulja stupnja {degree} treba najmanje ovoliko točaka: {min}",
  "interpolateApproximate.maxPoints": "ova demonstracija dopušta najviše {max} točaka",
  "interpolateApproximate.control.count": "Kontrolne točke (sve = interpolacija)",
  "interpolateApproximate.control.count.input": "broj kontrolnih točaka",
  "interpolateApproximate.countRange":
    "broj kontrolnih točaka mora biti cijeli broj od {min} (stupanj + 1) do {max} (broj točaka), dobiveno „{value}”",
  "interpolateApproximate.controlPoints.few": "{count} kontrolne točke",
  "interpolateApproximate.controlPoints.one": "{count} kontrolnom točkom",
  "interpolateApproximate.controlPoints.other": "{count} kontrolnih točaka",
  "interpolateApproximate.note.control":
    "Točke su kontrolni poligon: krivulja počinje u P₀, završava u Pₙ i samo se približava ostalima.",
  "interpolateApproximate.note.interpolation":
    "Interpolacija: jedna kontrolna točka po zadanoj točki, krivulja prolazi kroz svaku pₖ (najveći ostatak {max}).",
  "interpolateApproximate.note.leastSquares":
    "Najmanji kvadrati, krajevi točni: Σ |pₖ − C(tₖ)|² = {sum}; najveći ostatak {max} (u p{k}).",
  "interpolateApproximate.legendCurve": "B-krivulja C(u)",
  "interpolateApproximate.legendGiven": "kontrolni poligon: same točke",
  "interpolateApproximate.legendFitted": "kontrolni poligon rⱼ (izračunat)",
  "interpolateApproximate.legendResidual": "ostatak pₖ − C(tₖ)",
  "interpolateApproximate.tex.control": "stegnuti uniformni uzlovi",
  "interpolateApproximate.whatYouSee":
    "Iste točke mogu imati dvije uloge. Kao kontrolne točke oblikuju B-krivulju koja počinje u prvoj, završava u posljednjoj i samo se približava ostalima — aproksimacija interaktivnog oblikovanja iz bilježaka. Kao zadane točke (s parametrima tₖ po duljini tetiva) kroz njih točno prolazi interpolacijska B-krivulja s jednako mnogo kontrolnih točaka ili se, s manje kontrolnih točaka, aproksimiraju metodom najmanjih kvadrata uz točne oba kraja: kratke dužine od svake točke do krivulje su ostaci pₖ − C(tₖ), a sivi kvadratići na iscrtkanom poligonu izračunate kontrolne točke. Poglavlje 5 nastavnog programa (interpolacija i aproksimacija), prema hrvatskim i grčkim bilješkama.",
  "interpolateApproximate.try1":
    "Prebacujte između kontrolnih i zadanih točaka: kao kontrolne točke krivulja siječe unutar svakog vrha i dodiruje samo P₀ i P₉; kao podaci prolazi blizu svake točke, a uz broj 10 kroz svaku od njih.",
  "interpolateApproximate.try2":
    "Kao podaci, smanjujte broj kontrolnih točaka od 10 do 4: krivulja se opušta, dužine ostataka rastu, a zbroj kvadrata penje se od 0 do otprilike 78 — ne u svakom koraku (svaki broj dobiva vlastite uzlove), ali prva i posljednja točka uvijek ostaju točne.",
  "interpolateApproximate.try3":
    "Postavite broj na 10 (interpolacija) i naglo povucite p₄ prema dolje: cijela se krivulja nabire da bi prošla kroz nju. Smanjite broj na 5 i povucite ponovno: prilagođena krivulja samo se nagne prema točki, a umjesto toga raste njezin ostatak.",
  "app.language": "Jezik",
  "section.7": "7 · Interaktivno oblikovanje",
  "gallery.lecture": "Predavanje: ovo poglavlje scenu po scenu, za projekciju",
  "gallery.exercise": "Zadatak: {title}",
  "exercise.label": "Zadatak",
  "exercise.check": "Provjeri",
  "exercise.hint": "Uputa",
  "exercise.solved": "Riješeno: jezgra to potvrđuje.",
  "exercise.unknown": "Nema zadatka „{id}”.",
  "exercise.close-the-gap.title": "Zatvorite procjep",
  "exercise.close-the-gap.task":
    "Dvije se kubne krivulje ne spajaju. Povucite Q₀ na P₃ tako da krivulja bude neprekinuta (C⁰).",
  "exercise.close-the-gap.hint":
    "C⁰ zahtijeva samo da posljednja točka prvog segmenta bude prva točka drugog: Q₀ = P₃ = (4; 1).",
  "exercise.close-the-gap.notYet": "Još ne: Q₀ je od P₃ udaljena {detail}.",
  "exercise.make-it-c1.title": "Učinite spoj C¹",
  "exercise.make-it-c1.task":
    "Segmenti se spajaju, ali pod kutom. Pomaknite Q₁ tako da spoj bude C¹: ista derivacija s obje strane.",
  "exercise.make-it-c1.hint":
    "Za dvije kubne krivulje C¹ znači 3(P₃ − P₂) = 3(Q₁ − Q₀), pa je Q₁ = 2P₃ − P₂ = (5; −1).",
  "exercise.make-it-c1.notYet": "Još ne: jezgra u spoju mjeri C{detail}.",
  "exercise.bezier-pieces.title": "Razrežite krivulju na Bézierove segmente",
  "exercise.bezier-pieces.task":
    "Umetnite uzlove tako da svaki unutarnji uzao dobije višestrukost p = 2: tada se krivulja raspada na kvadratne Bézierove segmente.",
  "exercise.bezier-pieces.hint":
    "Unutarnji uzlovi su 1, 2 i 3, svaki jednom. Umetnite svaki od njih još jednom: postavite u na vrijednost uzla i pritisnite „Umetni”.",
  "exercise.bezier-pieces.notYet":
    "Još ne: broj unutarnjih uzlova u kojima je krivulja još C¹: {detail}.",
  "exercise.quarter-circle.title": "Četvrtina kružnice",
  "exercise.quarter-circle.task":
    "Kontrolne točke (4; 0), (4; 4), (0; 4) čine jednakokračni trokut. Odaberite težinu w₁ tako da luk bude točno četvrtina kružnice polumjera 4 sa središtem u (0; 0).",
  "exercise.quarter-circle.hint":
    "Za kružni luk w₁ je kosinus polovine središnjeg kuta luka: ovdje je taj kut 90°, pa je w₁ = cos 45° = √2/2 ≈ 0,7071.",
  "exercise.quarter-circle.notYet": "Još ne: polumjer duž luka varira za {detail} %.",
  "exercise.natural-ends.title": "Prirodni splajn",
  "exercise.natural-ends.task":
    "Ovaj splajn koristi rubni uvjet not-a-knot. Promijenite ga tako da splajn bude prirodan: bez savijanja na krajevima.",
  "exercise.natural-ends.hint":
    "Prirodan znači C″ = 0 na oba kraja: odaberite rubni uvjet „prirodni”.",
  "exercise.natural-ends.notYet": "Još ne: |C″| na krajevima iznosi {detail}.",
  "exercise.horn-torus.title": "Rogati torus",
  "exercise.horn-torus.task":
    "Promijenite torus tako da njegova cijev dodiruje os rotacije: rogati torus.",
  "exercise.horn-torus.hint":
    "Kružnica cijevi ima središte u (R, 0, 0) i polumjer r; dodiruje os z kada je R = r.",
  "exercise.horn-torus.notYet": "Još ne: cijev je od osi udaljena {detail}.",
  "exercise.through-every-point.title": "Kroz svaku točku",
  "exercise.through-every-point.task":
    "Krivulja dodiruje samo prvu i posljednju točku. Ne pomičući nijednu točku, učinite da prolazi kroz sve.",
  "exercise.through-every-point.hint":
    "Odaberite da točke budu zadane točke umjesto kontrolnih, s onoliko kontrolnih točaka koliko je zadanih točaka: interpolacija umjesto aproksimacije.",
  "exercise.through-every-point.notYet":
    "Još ne: broj točaka kroz koje krivulja prolazi: {detail}.",
  "lecture.label": "Predavanje",
  "lecture.previous": "← Prethodna",
  "lecture.next": "Sljedeća →",
  "lecture.counter": "{k} / {n}",
  "lecture.unknown": "Nema predavanja „{id}”.",
  "lecture.loadFailed": "Predavanje „{id}” nije se moglo učitati (HTTP {status}).",

  // ---- The curve library's errors by code (lib/core-errors.js; English: lib/strings/core-errors.js) ----
  "coreError.number.nan": "NaN",
  "coreError.number.infinity": "∞",
  "coreError.number.negativeInfinity": "−∞",
  "coreError.indexed": "{subject} {index}",
  "coreError.spacing.uniform": "uniformna",
  "coreError.spacing.chord": "tetivna",
  "coreError.spacing.centripetal": "centripetalna",
  "coreError.spacing.alpha": "alpha = {alpha}",
  "coreError.end.first": "prvih",
  "coreError.end.last": "posljednjih",
  "coreError.bufferLength": "duljina {length}",
  "coreError.invalid-dimension": "dim mora biti 2 ili 3, dobiveno {dim}",
  "coreError.coordinate-count":
    "broj koordinata {count} nije višekratnik od dim = {dim}; točke se zadaju ravno [{firstPoint}, x1, …]",
  "coreError.not-finite":
    "{subject}: vrijednost {value} nije dopuštena; svaki broj mora biti konačan",
  "coreError.coordinate-too-large":
    "{subject}: vrijednost {value} je prevelika; koordinata po apsolutnoj vrijednosti smije biti najviše {max}, kako bi derivacije i duljine ostale konačne",
  "coreError.too-few-points.one":
    "{what}: potrebna je barem {needed} kontrolna točka, dobiveno {got}",
  "coreError.too-few-points.few":
    "{what}: potrebne su barem {needed} kontrolne točke, dobiveno {got}",
  "coreError.too-few-points.other":
    "{what}: potrebno je barem {needed} kontrolnih točaka, dobiveno {got}",
  "coreError.weight-count":
    "težine moraju imati po jednu vrijednost za svaku kontrolnu točku ({expected}), dobiveno {got}",
  "coreError.non-positive-weight":
    "težina {index} iznosi {value}; težine moraju biti > 0 (nula ili negativne težine mogu stvoriti polove na krivulji)",
  "coreError.parameter-out-of-range": "{name} = {value} je izvan domene [{min}; {max}]",
  "coreError.index-out-of-range":
    "indeks kontrolne točke {index} je izvan raspona: krivulja ima {count} točaka (0..={last})",
  "coreError.point-dimension": "točka treba {expected} koordinate, dobiveno {got}",
  "coreError.invalid-tolerance":
    "tolerancija {value} nije upotrebljiva: mora biti konačan broj > 0",
  "coreError.tolerance-too-small":
    "tolerancija {value} nije upotrebljiva: manja je od {relative} × veličina krivulje ({size}); prevladale bi pogreške zaokruživanja",
  "coreError.flattening-stalled":
    "tolerancija {value} nije upotrebljiva: nijedan dio krivulje nije dovoljno ravan uz tu preciznost",
  "coreError.invalid-interval": "interval [{a}; {b}] je prazan; potrebno je a < b",
  "coreError.unknown-option": "{name} mora biti jedno od {expected}, dobiveno „{value}”",
  "coreError.in-argument": "{argument}: {message}",
  "coreError.knot-count":
    "vektor uzlova mora imati n+p+2 = {n} + {degree} + 2 = {expected} vrijednosti, dobiveno {got}",
  "coreError.knot-order":
    "uzlovi ne smiju padati: u_{index} = {value} dolazi nakon u_{previousIndex} = {previous}",
  "coreError.empty-domain":
    "domena [u_p, u_(n+1)] = [u_{degree}, u_{points}] = [{a}; {b}] je prazna; potrebno je u_{degree} < u_{points}",
  "coreError.knot-multiplicity":
    "uzao {knot} pojavljuje se {multiplicity} puta (u_{first}..u_{last}); krivulja stupnja {degree} dopušta najviše p+1 = {order}",
  "coreError.insertion-multiplicity.one":
    "umetanje uzla {knotValue} {times} put dalo bi mu višestrukost {multiplicity}; stupanj {degree} dopušta najviše p+1 = {order}",
  "coreError.insertion-multiplicity.few":
    "umetanje uzla {knotValue} {times} puta dalo bi mu višestrukost {multiplicity}; stupanj {degree} dopušta najviše p+1 = {order}",
  "coreError.insertion-multiplicity.other":
    "umetanje uzla {knotValue} {times} puta dalo bi mu višestrukost {multiplicity}; stupanj {degree} dopušta najviše p+1 = {order}",
  "coreError.degree-zero": "stupanj mora biti barem 1, dobiveno 0",
  "coreError.degree-out-of-range": "stupanj mora biti 1..={max}, dobiveno {degree}",
  "coreError.too-few-points-for-degree":
    "stupanj {degree} traži barem p+1 = {order} kontrolnih točaka, dobiveno {got}",
  "coreError.coincident-points":
    "točke {index} i {next} se podudaraju; {kind} parametrizacija traži različite uzastopne točke",
  "coreError.phantom-even-degree":
    "fantomske točke čine da uniformna B-krivulja neparnog stupnja prolazi krajnjim točkama; stupanj {degree} je paran",
  "coreError.not-a-span": "interval {span} nije neprazan interval domene (valjani: [{valid}])",
  "coreError.rational-join":
    "pravila spajanja vrijede za polinomne Bézierove dijelove; ovi imaju težine",
  "coreError.join-degree.one":
    "pravilo {rule} određuje {needed} točku desnog dijela; stupnjevi {left} i {right} su preniski (svaki dio treba stupanj >= {needed})",
  "coreError.join-degree.few":
    "pravilo {rule} određuje {needed} točke desnog dijela; stupnjevi {left} i {right} su preniski (svaki dio treba stupanj >= {needed})",
  "coreError.join-degree.other":
    "pravilo {rule} određuje {needed} točaka desnog dijela; stupnjevi {left} i {right} su preniski (svaki dio treba stupanj >= {needed})",
  "coreError.no-joint-tangent":
    "G1 traži tangentu u spoju, ali se posljednje dvije točke lijevog dijela podudaraju",
  "coreError.breakpoint-count":
    "broj dijelova: {pieces}; potrebno je {breakpoints} točaka loma, dobiveno {got}",
  "coreError.degenerate-line": "pravac treba dvije različite točke, dvaput je dobivena ({x}; {y})",
  "coreError.curve-batch-length":
    "{count} koordinata ne dijeli se na krivulje stupnja {degree} ((degree + 1)·dim = {perCurve} brojeva svaka)",
  "coreError.rational-hodograph":
    "hodograf racionalne krivulje nije Bézierova krivulja stupnja n − 1; umjesto toga uzorkujte derivative(t, 1)",
  "coreError.mapped-weight":
    "preslikavanje šalje kontrolnu točku {index} u težinu {weight}; težine moraju ostati > 0 (točka bi prešla beskonačno daleki pravac)",
  "coreError.singular-map": "projektivno preslikavanje je singularno (determinanta 0)",
  "coreError.matrix-size":
    "projektivno preslikavanje je matrica 3×3 (9 brojeva, redak po redak), dobiveno {got}",
  "coreError.degenerate-triangle":
    "kružni luk treba pravi trokut P0 P1 P2 (bez podudarnih ili kolinearnih točaka)",
  "coreError.not-isosceles":
    "kružni luk treba jednakokračan trokut: |P0P1| = {first}, ali |P1P2| = {second}",
  "coreError.arc-point-count": "kružni luk treba 3 kontrolne točke (6 brojeva), dobiveno {got}",
  "coreError.invalid-sweep":
    "središnji kut luka mora biti različit od nule i najviše jedan puni okret (2π), dobiveno {sweep}",
  "coreError.parallel-axes": "dvije osi elipse ne smiju biti paralelne ni nul-vektori",
  "coreError.axis-lengths":
    "center, axisX i axisY moraju imati istu duljinu, dobiveno {center}, {axisX}, {axisY}",
  "coreError.not-positive": "{name}: mora biti > 0, dobiveno {value}",
  "coreError.dimension-mismatch": "oba dijela moraju imati isti dim, dobiveno {left} i {right}",
  "coreError.piece-point-count":
    "stupnjevi [{degrees}] traže ukupno {needed} kontrolnih točaka (n + 1 po dijelu), dobiveno {got}",
  "coreError.buffer-length":
    "izlazni spremnik ima {len} vrijednosti, a broj točaka {count} traži {needed}",
  "coreError.net-coordinate-count":
    "točke moraju sadržavati rows·cols·3 = {rows}·{cols}·3 = {total} koordinata, dobiveno {got}",
  "coreError.patch-too-small":
    "Bézierova krpica treba barem 2 retka i 2 stupca (stupanj ≥ 1 u svakom smjeru), dobiveno {rows} × {cols}",
  "coreError.net-index-out-of-range":
    "kontrolna točka (i, j) = ({i}; {j}) je izvan raspona: mreža ima {rows} × {cols} točaka (i u 0..={lastI}, j u 0..={lastJ})",
  "coreError.no-normal":
    "površina nema normalu u (u, v) = ({u}; {v}): ondje je ∂S/∂u × ∂S/∂v = 0, čak i u limesu iz unutrašnjosti domene",
  "coreError.empty-tessellation":
    "tessellate treba barem 1 četverokut u svakom smjeru, dobiveno nu = {nu}, nv = {nv}",
  "coreError.too-large": "{what} = {value}: previše; dopušteno je najviše {max}",
  "coreError.result-too-large":
    "{what} = {counts} vrijednosti po {valueBytes} bajtova = {bytes} bajtova je previše; jedan rezultat smije zauzeti najviše {maxBytes} bajtova ({mib} MiB)",
  "coreError.argument-type": "{name} mora biti {expected}, dobiveno {got}",
  "coreError.not-whole-number": "{subject}: mora biti cijeli broj od 0 do {max}, dobiveno {value}",
  "coreError.needs-2d": "{operation} radi na 2D krivuljama; ova krivulja ima dim = {dim}",
  "coreError.needs-3d":
    "{operation} gradi 3D površinu i treba 3D krivulju; ova krivulja ima dim = {dim}",
  "coreError.zero-direction": "{name} ne smije biti nul-vektor (ne daje smjer)",
  "coreError.needs-polynomial":
    "{operation} radi na polinomnim krpicama; ova ima težine (racionalna krpica ima nazivnik)",
  "coreError.all-weights-zero":
    "sve težine ({count}) su 0: nazivnik w(t) = Σ w_i B_i(t) je 0 za svaki t, pa krivulje nema",
  "coreError.param-count":
    "params moraju imati po jednu vrijednost za svaku točku ({points}), dobiveno {params}",
  "coreError.params-not-increasing":
    "params moraju strogo rasti: t_{index} = {value} nije veće od t_{previousIndex} = {previous}",
  "coreError.missing-argument": "{neededBy}: potreban je {name}, a nije zadan",
  "coreError.argument-length": "{name} mora imati {expected} brojeva, dobiveno {got}",
  "coreError.not-closed":
    "periodička interpolacija traži da posljednja točka (točka {last}) bude jednaka prvoj",
  "coreError.alpha-out-of-range":
    "alpha = {value} je izvan [0; 1] (0 uniformna; 0,5 centripetalna; 1 tetivna)",
  "coreError.control-count-out-of-range":
    "count = {count} kontrolnih točaka je izvan [stupanj + 1, broj točaka] = [{min}; {max}]",
  "coreError.schoenberg-whitney":
    "interpolacijski sustav je singularan: t_{index} = {param} mora ležati unutar nosača (u_{index}, u_{hiIndex}) = ({lo}; {hi}) od N_{index},{degree} (Schoenberg–Whitneyjev uvjet)",
  "coreError.too-few-data-points.one":
    "{what}: potrebna je barem {needed} zadana točka, dobiveno {got}",
  "coreError.too-few-data-points.few":
    "{what}: potrebne su barem {needed} zadane točke, dobiveno {got}",
  "coreError.too-few-data-points.other":
    "{what}: potrebno je barem {needed} zadanih točaka, dobiveno {got}",
  "coreError.stroke-far-from-curve":
    "potez počinje na udaljenosti {startDistance} i završava na udaljenosti {endDistance} od krivulje; da biste ponovno nacrtali dio krivulje, počnite i završite potez unutar {near} od nje (otvorena krivulja produžuje se i potezom koji na njoj počinje ili završava)",
  "coreError.singular-system":
    "{what}: sustav je singularan; eliminacija je naišla na nul-pivot u retku {row}",
  "coreError.spline-kind":
    "{operation} radi na splajnovima izgrađenima s {needs}; ovaj je izgrađen s {got}",
  "coreError.conflicting-options": "{first} se ne može kombinirati s {second}: {reason}",
  "coreError.knots-not-clamped":
    "aproksimacija najmanjim kvadratima s točnim krajevima traži stegnute uzlove: {end} p+1 = {order} uzlova mora biti jednako {param}",
  "coreError.freed": "ovaj {className} je oslobođen (free)",
  "coreError.no-constructor": "new {className}() nije dostupan: {className} se dobiva iz {makers}",
  "coreError.out-buffer":
    "out mora biti Float64Array ili number[] s barem dim = {dim} brojeva, dobiveno {got}",
  "coreError.internal": "unutarnja pogreška biblioteke krivulja: {message}",
  "coreError.place.pieceField": "pieces[{piece}].{field}",
  "coreError.place.piece": "pieces[{piece}]",
  "coreError.place.field": "{field}",
  "coreError.place.none": "izraz",
  "coreError.place.range": "{place}, znakovi {start}–{end}",
  "coreError.place.at": "{place}: {message}",
  "coreError.expression-empty": "ništa nije upisano; upišite izraz u t, na primjer cos(t)",
  "coreError.expression-too-long": "izraz ima {length} znakova; dopušteno je najviše {max}",
  "coreError.expression-too-deep":
    "zagrade, potencije i funkcije ugniježđene su dublje od {max} razina",
  "coreError.expression-too-large": "izraz ima više od {max} brojeva, imena i operacija",
  "coreError.unexpected-character":
    "„{character}” nije dio jezika; koristite brojeve, t, + − * / ^ i zagrade",
  "coreError.unexpected-character.comma":
    "„,” se ne koristi: decimalne brojeve pišite s točkom (2.5)",
  "coreError.unexpected-character.bar": "„|” se ne koristi: pišite abs(t)",
  "coreError.expected-operand": "prije „{found}” potreban je broj, ime ili „(”",
  "coreError.expected-operand.end": "izraz završava ondje gdje je potreban broj, ime ili „(”",
  "coreError.missing-operator": "nedostaje operator prije „{found}” (napišite * ili + između)",
  "coreError.unclosed-parenthesis": "ova „(” nikad se ne zatvara; dodajte „)”",
  "coreError.unmatched-parenthesis": "ova „)” nema „(” prije sebe",
  "coreError.unknown-name":
    "nepoznato ime „{name}”; koristite t, pi, e, funkciju poput sin(t) ili parametar",
  "coreError.function-needs-parentheses": "{name} treba zagrade: napišite {name}(t)",
  "coreError.function-power":
    "{name}^ treba prirodni broj ≥ 1 prije zagrada: {name}^2(t) znači ({name}(t))^2",
  "coreError.function-power.trig":
    "{name}^ treba prirodni broj ≥ 1 (sin^2(t)); inverzna funkcija je a{name}(t)",
  "coreError.ambiguous-division": "„{text}” je dvosmisleno: napišite {product} ili {quotient}",
  "coreError.number-after-name": "broj iza imena: napišite {number}{name} ili {name}^{number}",
  "coreError.scientific-notation":
    "„{text}” se ne čita kao potencija broja deset (e je Eulerov broj): napišite decimalni broj, na primjer 0.001, ili umnožak, na primjer 2.5*10^3",
  "coreError.invalid-number": "„{text}” nije broj",
  "coreError.invalid-parameter-name":
    "„{name}” ne može biti parametar: koristite jedno slovo osim t i e (a, b, ω) ili slovo s indeksom (a_1)",
  "coreError.unknown-parameter": "krivulja nema parametar „{name}”",
  "coreError.not-finite-value": "vrijednost je {value}; mora biti konačan broj",
  "coreError.empty-piece-interval": "interval [{from}; {to}] je prazan; potrebno je from < to",
  "coreError.pieces-do-not-join":
    "počinje u {from}, a prethodni segment završava u {previous}; segmenti se spajaju po t",
  "coreError.missing-field":
    "ovo polje nedostaje; svaki segment treba x, y, from i to (i z na svim segmentima ili ni na jednom)",
  "coreError.piece-count": "krivulja treba od 1 do {max} segmenata, zadano je {count}",
  "coreError.not-polynomial": "ovaj segment nije polinom u t, pa nema Bézierov oblik",
  "coreError.bound-uses-t":
    "granica je broj i ne može ovisiti o t; napišite je brojevima, s pi, e i parametrima",
  "coreError.subject.adaptive-depth":
    "dubina adaptivne podjele (tolerancija je blizu pogreške zaokruživanja)",
  "coreError.subject.adaptive-vertices": "vrhovi adaptivne mreže",
  "coreError.subject.adaptive-vertices-leaves": "vrhovi adaptivne mreže (barem jedan po listu)",
  "coreError.subject.adaptive-vertices-patches":
    "vrhovi adaptivne mreže (barem jedan po Bézierovoj krpici)",
  "coreError.subject.basis-sample-count":
    "count (uzorci po baznoj funkciji: svaki po jedna vrijednost za svaku funkciju)",
  "coreError.subject.bessel-spline": "Besselov splajn",
  "coreError.subject.bezier-curve": "Bézierova krivulja",
  "coreError.subject.boolean": "logička vrijednost (boolean)",
  "coreError.subject.bspline-interpolation-system": "sustav interpolacije B-krivuljom",
  "coreError.subject.cardinal-spline": "kardinalni splajn",
  "coreError.subject.catmull-rom-spline": "Catmull–Rom splajn",
  "coreError.subject.clamped-end-condition": "rubni uvjet „clamped” (stegnuti)",
  "coreError.subject.closed-has-no-ends": "zatvorena krivulja nema krajeva",
  "coreError.subject.closed-interpolating-bspline":
    "zatvorena interpolacijska B-krivulja ovog stupnja (p + 1, barem 3)",
  "coreError.subject.closed-knots-computed":
    "uzlovi zatvorene krivulje su periodički, izračunati iz params",
  "coreError.subject.composite-curve": "složena krivulja (dijelovi)",
  "coreError.subject.coordinate": "koordinata",
  "coreError.subject.cubic-spline": "kubni splajn",
  "coreError.subject.cubic-spline-system": "sustav tangenti kubnog splajna",
  "coreError.subject.curvature-work": "točke zakrivljenosti za ovaj stupanj (proračun rada 2^28)",
  "coreError.subject.curve": "BSplineCurve ili BezierCurve",
  "coreError.subject.data-point-count": "broj zadanih točaka",
  "coreError.subject.degree-u-rows": "degreeU (retci duž u)",
  "coreError.subject.degree-v-columns": "degreeV (stupci duž v)",
  "coreError.subject.derivative-order": "red derivacije",
  "coreError.subject.every-piece": "svaki dio (stupanj >= 1)",
  "coreError.subject.flattening-segments": "broj segmenata linearizacije",
  "coreError.subject.flattening-segments-estimated":
    "broj segmenata linearizacije (procijenjen prije linearizacije: smanjite stupanj ili povećajte toleranciju)",
  "coreError.subject.grid-points": "točke mreže us.length·vs.length",
  "coreError.subject.hermite-spline": "Hermiteov splajn",
  "coreError.subject.interpolating-bspline":
    "interpolacijska B-krivulja ovog stupnja (p + 1 − derivacije na krajevima, barem 2)",
  "coreError.subject.interpolating-surface":
    "interpolacijska površina ovog stupnja (stupanj + 1 u svakom smjeru)",
  "coreError.subject.interpolation-system-size": "veličina interpolacijskog sustava (nepoznanice)",
  "coreError.subject.knot": "uzao",
  "coreError.subject.knot-to-insert": "uzao za umetanje",
  "coreError.subject.lagrange-curve": "Lagrangeova krivulja",
  "coreError.subject.lagrange-point-count": "broj točaka Lagrangeove krivulje",
  "coreError.subject.least-squares-bspline":
    "B-krivulja najmanjih kvadrata ovog stupnja (p + 1, barem 2)",
  "coreError.subject.least-squares-system": "normalne jednadžbe najmanjih kvadrata",
  "coreError.subject.length": "njegova duljina",
  "coreError.subject.matrix-entry": "element matrice",
  "coreError.subject.new-point-coordinate": "koordinata nove točke",
  "coreError.subject.numbers": "niz brojeva (Float64Array ili number[])",
  "coreError.subject.object": "objekt",
  "coreError.subject.parameter": "parametar",
  "coreError.subject.parametrisation": "parametrizacija",
  "coreError.subject.phantom-points": "fantomske točke ovog stupnja",
  "coreError.subject.polynomial": "polinom",
  "coreError.subject.rational-bezier-curve": "racionalna Bézierova krivulja",
  "coreError.subject.rational-derivative-order": "red derivacije racionalne krivulje",
  "coreError.subject.refine-result": "refine: (kontrolne točke + us.length) × homogene koordinate",
  "coreError.subject.sample-count": "broj uzoraka",
  "coreError.subject.sample-work": "broj uzoraka za ovaj stupanj (proračun rada 2^28)",
  "coreError.subject.sample-derivatives-result": "sampleDerivatives: us.length × koordinate",
  "coreError.subject.sample-grid-result": "sampleGrid: us.length × vs.length × 3 koordinate",
  "coreError.subject.sample-params-result": "sample: params.length × koordinate",
  "coreError.subject.sample-ts-result": "sample: ts.length × koordinate",
  "coreError.subject.sample-uniform-result": "sampleUniform: count × koordinate",
  "coreError.subject.sample-uniform-view-result": "sampleUniformView: count × koordinate",
  "coreError.subject.sample-view-result": "sampleView: params.length × koordinate",
  "coreError.subject.samples-result": "uzorci (točke × koordinate)",
  "coreError.subject.start-angle": "početni kut",
  "coreError.subject.string": "znakovni niz (string)",
  "coreError.subject.stroke": "potez",
  "coreError.subject.surface-derivative-order": "red derivacije du + dv",
  "coreError.subject.tessellation-vertices": "vrhovi teselacije (nu + 1)(nv + 1)",
  "coreError.subject.tessellation-work":
    "vrhovi teselacije (nu + 1)(nv + 1) za ovaj stupanj (proračun rada 2^28)",
  "coreError.subject.weight": "težina",
  // The typed piecewise curve (section 1, www/demos/piecewise.js) and its exercise.
  "piecewise.title": "Krivulje po dijelovima i njihovi spojevi",
  "piecewise.summary":
    "Upišite x(t), y(t) i interval svakog segmenta; jezgra svaki spoj označava kao Cᵏ ili Gᵏ, dokazuje to gdje može i prikazuje jednostrane vrijednosti jednu uz drugu.",
  "piecewise.aria": "Krivulja od {count} segmenata upisanih formulama; spojevi: {joints}",
  "piecewise.ariaNoJoints": "Krivulja od jednog segmenta upisanog formulom: nema spoja",
  "piecewise.whatYouSee":
    "Svaki segment Pᵢ(t) = (x(t), y(t)) nacrtan je svojom bojom na svojem intervalu; gdje jedan interval završava, počinje sljedeći (poglavlje 1 nastavnog programa: segmenti na [0, 1) i [1, 2]). U svakom spoju strelice su brzine koje dolaze, P′(t⁻), i odlaze, P′(t⁺); tablica ispod slike navodi jednostrane vrijednosti x(t⁻), x(t⁺), x′(t⁻), x′(t⁺), … i prvi red derivacije u kojem se razlikuju. Ocjena Cᵏ (parametarski kontinuitet: derivacije do reda k se podudaraju) ili Gᵏ (geometrijski kontinuitet: samo oblik, tj. smjer, zatim zakrivljenost) dolazi iz jezgre, dokazana egzaktnom aritmetikom za polinomne segmente.",
  "piecewise.try1":
    "Pritisnite „C⁰, nije C¹”: x′(1⁻) = −2, ali x′(1⁺) = 0, pa brzina skače i krivulja ima šiljak. Zatim pritisnite „C¹”: x′ se podudara, skače samo x″.",
  "piecewise.try2":
    "U segment 2 sami upišite x(t) = t^2 - 4t + 3, zatim promijenite 3 u 4: spoj puca (nije C⁰), a slika pokazuje procjep.",
  "piecewise.try3":
    "Pritisnite „G¹, nije C¹”: drugi segment je ista parabola prijeđena dvostrukom brzinom, pa je oblik gladak (G¹ i više) iako se P′ u t = 1 udvostručuje.",
  "piecewise.pieces": "Segmenti",
  "piecewise.piece": "Segment {i}",
  "piecewise.field.x": "x(t) =",
  "piecewise.field.y": "y(t) =",
  "piecewise.field.from": "od t =",
  "piecewise.field.to": "do t =",
  "piecewise.field.name": "{field} segmenta {i}",
  "piecewise.fieldName.x": "x(t)",
  "piecewise.fieldName.y": "y(t)",
  "piecewise.fieldName.from": "početak intervala",
  "piecewise.fieldName.to": "kraj intervala",
  "piecewise.addPiece": "Dodaj segment",
  "piecewise.addPiece.title": "Dodaj segment iza posljednjeg, od mjesta gdje on završava",
  "piecewise.removePiece": "Ukloni posljednji segment",
  "piecewise.removePiece.title": "Ukloni posljednji segment (ostaje barem jedan)",
  "piecewise.maxPieces": "ovaj primjer dopušta najviše {max} segmenata",
  "piecewise.minPieces": "krivulji treba barem jedan segment",
  "piecewise.typingError": "Segment {i}, {field}: {message}",
  "piecewise.presets": "Zadatak iz bilježaka i više",
  "piecewise.preset.title": "Zamijeni segmente ovim primjerom",
  "piecewise.preset.notC0": "Nije C⁰",
  "piecewise.preset.c1": "C¹",
  "piecewise.preset.c0": "C⁰, nije C¹",
  "piecewise.preset.g1": "G¹, nije C¹",
  "piecewise.jointsLegend": "Spojevi",
  "piecewise.noJoints": "Jedan segment: nema spoja za provjeru.",
  "piecewise.joint": "t = {t}: {verdict}",
  "piecewise.verdict": "{c}, {g}",
  "piecewise.verdict.broken": "nije C⁰: segmenti se ne spajaju",
  "piecewise.verdict.infinite": "C∞: obje strane su jedan polinom",
  "piecewise.proven": "dokazano (egzaktna aritmetika)",
  "piecewise.measured": "izmjereno (aritmetika s pomičnim zarezom)",
  "piecewise.breakProven":
    "izmjereno (aritmetika s pomičnim zarezom); da se red {order} razlikuje, dokazano je (intervalna aritmetika)",
  "piecewise.figureVerdict": "t = {t}: {verdict} ({how})",
  "piecewise.tag": "t = {t}",
  "piecewise.leftArrow": "P′({t}⁻)",
  "piecewise.rightArrow": "P′({t}⁺)",
  "piecewise.incomplete":
    "Dio krivulje nije se mogao profiniti unutar proračuna rada; ondje je nacrtan grublje.",
  "piecewise.tableCaption": "Spoj u t = {t}: {verdict}, {how}",
  "piecewise.col.quantity": "Vrijednost",
  "piecewise.col.left": "slijeva (t⁻)",
  "piecewise.col.right": "zdesna (t⁺)",
  "piecewise.col.agree": "Podudaraju se?",
  "piecewise.agree.yes": "da",
  "piecewise.agree.no": "ne",
  "piecewise.undefined": "nije definirano",
  "piecewise.formula.joint": "spoj u",
  "piecewise.formula.proven": "dokazano",
  "piecewise.formula.measured": "izmjereno",
  "piecewise.formula.breakProven": "izmjereno; red {order} se razlikuje: dokazano",
  "piecewise.formula.notC0": "nije C⁰",
  "piecewise.badPiece":
    "polje „{field}”: segment {index} mora biti [x, y, from, to] s tekstovima od najviše 1000 znakova",
  "exercise.piecewise-c1.title": "Upišite drugi segment sa spojem C¹",
  "exercise.piecewise-c1.task":
    "Segment 1 je x = 1 − t², y = t na [0, 1]. Upišite x(t) i y(t) segmenta 2 na [1, 2] tako da spoj u t = 1 bude C¹: ista točka i ista brzina s obje strane.",
  "exercise.piecewise-c1.hint":
    "U t = 1 segment 1 je u točki x = 0, y = 1 s brzinom x′ = −2, y′ = 1. Zadržite y = t i potražite x = t² + bt + c uz x(1) = 0 i x′(1) = 2 + b = −2.",
  "exercise.piecewise-c1.notYet": "Još ne. Ocjena jezgre u t = 1: {detail}.",
  // ---- parametric-curve (section 1) ----
  "parametricCurve.title": "Parametarske krivulje iz formula",
  "parametricCurve.summary":
    "Upišite x(t), y(t) (i z(t)) i gledajte točku kako se giba po P(t) s brzinom, akceleracijom, zakrivljenošću i oskulacijskom kružnicom, a uz nju hodograf.",
  "parametricCurve.aria":
    "Parametarska krivulja x(t) = {x}, y(t) = {y} za t od {a} do {b}; t = {t}; P(t) = ({px}; {py}); iznos brzine {speed}; zakrivljenost κ = {kappa}; hodograf je nacrtan pokraj nje",
  "parametricCurve.aria3d":
    "Prostorna krivulja x(t) = {x}, y(t) = {y}, z(t) = {z} za t od {a} do {b}; t = {t}; P(t) = ({px}; {py}; {pz}); iznos brzine {speed}; zakrivljenost κ = {kappa}; torzija τ = {tau}; Frenetov trobrid T, N, B nacrtan je u P(t)",
  "parametricCurve.ariaUndefined":
    "Parametarska krivulja x(t) = {x}, y(t) = {y} za t od {a} do {b}; u t = {t} krivulja nije definirana",
  "parametricCurve.whatYouSee":
    "Krivulja je točka koja se giba: P(t) = (x(t), y(t)) za t iz [a, b] (poglavlje 1 nastavnog programa; kružnica x = cos t, y = sin t na [0, 2π] iz bilježaka). Crveno-narančasta strelica je brzina P′(t), ljubičasta akceleracija P″(t); narančasta kružnica je oskulacijska kružnica polumjera 1/|κ|. Desno hodograf skuplja sve brzine P′(t), nacrtane iz točke O. Svaku formulu raščlanjuje i derivira biblioteka krivulja; svako ime osim t postaje klizač.",
  "parametricCurve.try1":
    "Pritisnite „Pokreni”, zatim odaberite „Cikloida”: u svakom šiljku iznos brzine pada na 0 i strelica brzine nestaje, a hodograf prolazi kroz O.",
  "parametricCurve.try2":
    "Odaberite „Elipsa” i pomičite klizače a i b: oskulacijska kružnica najmanja je na krajevima velike osi.",
  "parametricCurve.try3":
    "Odaberite „y = tan t”: graf se prekida u polovima t = ±π/2 umjesto da spaja grane.",
  "parametricCurve.try4":
    "Odaberite „Polinom iz bilježaka” i označite „Prikaži Bézierov oblik”: kontrolne točke su točni razlomci poput −271/50.",
  "parametricCurve.try5":
    "Upišite sin(t) u z(t): krivulja izlazi iz ravnine, a u P(t) se pojavljuje Frenetov trobrid T, N, B. Povlačenjem slike zakrećete je.",
  "parametricCurve.control.curve": "Krivulja P(t)",
  "parametricCurve.control.x": "x(t) =",
  "parametricCurve.control.y": "y(t) =",
  "parametricCurve.control.z": "z(t) = (prazno: ravninska krivulja)",
  "parametricCurve.control.from": "t od",
  "parametricCurve.control.to": "do",
  "parametricCurve.control.help":
    "Formule u t poput 2cos(t), t^2 - 1, e^(-t/5)sin(3t); π se piše pi. Svako drugo slovo (a, b, ω, a_1) je parametar s klizačem.",
  "parametricCurve.control.params": "Parametri",
  "parametricCurve.control.param.input": "vrijednost parametra {name}",
  "parametricCurve.control.t": "t",
  "parametricCurve.control.t.input": "vrijednost parametra t",
  "parametricCurve.control.examples": "Primjeri",
  "parametricCurve.preset.circle": "Kružnica",
  "parametricCurve.preset.ellipse": "Elipsa",
  "parametricCurve.preset.lissajous": "Lissajous",
  "parametricCurve.preset.cycloid": "Cikloida",
  "parametricCurve.preset.cardioid": "Kardioida",
  "parametricCurve.preset.astroid": "Astroida",
  "parametricCurve.preset.spiral": "Spirala",
  "parametricCurve.preset.helix": "Zavojnica (3D)",
  "parametricCurve.preset.tan": "y = tan t",
  "parametricCurve.preset.polynomial": "Polinom iz bilježaka",
  "parametricCurve.control.bezier": "Prikaži Bézierov oblik (polinomijalna krivulja)",
  "parametricCurve.bezierPoints": "Kontrolne točke na [{a}, {b}], točno: {list}",
  "parametricCurve.bezierLink": "Otvori ove kontrolne točke u De Casteljauovu algoritmu",
  "parametricCurve.bezierLinkOff":
    "Demonstracija De Casteljauova algoritma prima samo ravninske krivulje stupnja 1 do 10.",
  "parametricCurve.atT": "U t",
  "parametricCurve.speed": "Iznos brzine |P′(t)| = {speed}",
  "parametricCurve.curvature": "Zakrivljenost κ(t) = {kappa}",
  "parametricCurve.radius": "Oskulacijska kružnica polumjera {r}",
  "parametricCurve.torsion": "Torzija τ(t) = {tau}",
  "parametricCurve.undefined": "Krivulja nije definirana u t = {t} (pol ili praznina)",
  "parametricCurve.cusp": "P′(t) = 0: nema smjera gibanja, κ nije definirana",
  "parametricCurve.straight": "Ovdje ravna (κ ≈ 0): nema oskulacijske kružnice",
  "parametricCurve.pointLabel": "P(t)",
  "parametricCurve.velocityLabel": "P′(t)",
  "parametricCurve.accelerationLabel": "P″(t)",
  "parametricCurve.originLabel": "O",
  "parametricCurve.tangentLabel": "T",
  "parametricCurve.normalLabel": "N",
  "parametricCurve.binormalLabel": "B",
  "parametricCurve.hodographCaption": "Hodograf P′(t), ishodište O",
  "parametricCurve.scaleCaption": "Strelice i hodograf u mjerilu {scale}",
  "parametricCurve.frameCaption":
    "Frenetov trobrid T, N, B u P(t); povlačenjem zakrećete, Shift+povlačenjem pomičete",
  "parametricCurve.incomplete":
    "Nacrtano približno: negdje krivulja titra brže nego što je crtanje moglo pratiti",
  "parametricCurve.formula.undefined": "nije definirano",
  "parametricCurve.formula.tooLong": "predugo za prikaz",
  "parametricCurve.error.text": "polje „{field}”: formula je tekst od najviše {max} znakova",
  "parametricCurve.error.params":
    'polje „params”: vrijednosti parametara su konačni brojevi po imenu, poput {"a": 2}',
  // ---- end parametric-curve ----
  // ---- sketch (section 7, www/demos/sketch.js) and its exercise ----
  "sketch.title": "Skiciranje krivulje",
  "sketch.summary":
    "Nacrtajte potez: najmanje Bézierovih segmenata (ili kontrolnih točaka B-krivulje) koji ostaju unutar tolerancije, a kutovi se čuvaju; zatim uređujte povlačenjem točaka ili ponovnim crtanjem dijela.",
  "sketch.aria": "Skicirana krivulja: {fit}",
  "sketch.figureHelp":
    "Crtajte po slici mišem, olovkom ili prstom; potez koji počinje na krivulji ponovno crta taj dio. Povucite točku ili pritisnite Tab za odabir, a strelicama je pomičite (Shift: 10 px). Shift + povlačenje pomiče pogled; kotačić ili štipanje zumira.",
  "sketch.outputLegend": "Krivulja je",
  "sketch.output.G1": "Bézierovi segmenti, spojevi G¹",
  "sketch.output.C1": "Bézierovi segmenti, spojevi C¹",
  "sketch.output.bspline": "B-krivulja stupnja p",
  "sketch.control.degree": "Stupanj p",
  "sketch.control.degree.input": "stupanj B-krivulje",
  "sketch.control.tolerance": "Tolerancija (px zaslona)",
  "sketch.control.tolerance.input": "tolerancija u pikselima zaslona",
  "sketch.showLegend": "Prikaži",
  "sketch.control.corners": "kutove (i zaokret u njima)",
  "sketch.control.breaks": "točke podjele (spojeve)",
  "sketch.control.errors": "najveću pogrešku svakog segmenta i njezin uzorak",
  "sketch.control.polygon": "kontrolne poligone i točke (povucite ih)",
  "sketch.control.comb": "češalj zakrivljenosti",
  "sketch.control.oversketch": "Potez koji počinje na krivulji ponovno crta taj dio",
  "sketch.oversketchBezier":
    "Ponovno crtanje dijela mijenja Bézierove segmente: s B-krivuljom svaki potez je novi crtež.",
  "sketch.control.presets": "Primjeri poteza",
  "sketch.preset.wave": "Val",
  "sketch.preset.corners": "Cik-cak s kutovima",
  "sketch.preset.blob": "Zatvoreni oblik",
  "sketch.preset.spiral": "Spirala",
  "sketch.preset.letter": "Slovo S",
  "sketch.pieces.one": "{count} segment",
  "sketch.pieces.few": "{count} segmenta",
  "sketch.pieces.other": "{count} segmenata",
  "sketch.corners.one": "{count} kut",
  "sketch.corners.few": "{count} kuta",
  "sketch.corners.other": "{count} kutova",
  "sketch.controlPoints.one": "{count} kontrolna točka",
  "sketch.controlPoints.few": "{count} kontrolne točke",
  "sketch.controlPoints.other": "{count} kontrolnih točaka",
  "sketch.fitPieces":
    "{pieces}, {corners}; najveća pogreška {error} (tolerancija {tolerance} px); {shape}.",
  "sketch.fitBSpline":
    "B-krivulja stupnja {p} s {control}; najveća pogreška {error} (tolerancija {tolerance} px); {shape}.",
  "sketch.px": "{value} px",
  "sketch.notMeasured": "nije izmjerena",
  "sketch.open": "otvorena",
  "sketch.closed": "zatvorena",
  "sketch.edited":
    "Uređena nakon prilagodbe: oznake i pogreške pripadaju prilagodbi, prije izmjena.",
  "sketch.handle": "segment {piece}, {name}",
  "sketch.badStroke": "potez nije valjan zapis poteza (od 2 do 4000 točaka)",
  "sketch.badEdits": "popis izmjena nije valjan",
  "sketch.whatYouSee":
    "Široka svijetla linija je ono što ste nacrtali; plava krivulja je prilagodba biblioteke: kubični Bézierovi segmenti, njih što manje tako da svaki uzorak poteza bude unutar tolerancije ε (izmjereno, ne procijenjeno), ili jedna B-krivulja stupnja p sa što manje kontrolnih točaka. Gdje potez naglo skreće, prilagodba zadržava kut (spoj G⁰, kvadratna oznaka s kutom zaokreta); svaki drugi spoj je gladak, G¹ ili C¹. Zelene točke su točke podjele, isprekidane linije kontrolni poligon svakog segmenta, a češalj prikazuje zakrivljenost κ duž krivulje. Poglavlje 7 gradiva (interaktivno oblikovanje): „krivulja otprilike ovakva”, uređena bez počinjanja ispočetka.",
  "sketch.try1":
    "Brzo nacrtajte cik-cak pa pomaknite toleranciju s 1 px na 10 px: segmenti se spajaju, ali kutovi ostaju.",
  "sketch.try2":
    "Nacrtajte petlju koja završava gdje je počela: krivulja se zatvara, glatka na šavu. Uključite češalj zakrivljenosti: gdje κ skače?",
  "sketch.try3":
    "Počnite kratak potez na krivulji i završite ga na njoj malo dalje: ponovno se crta samo taj dio. Zatim povucite kontrolnu točku i pritisnite Ctrl+Z.",
  "exercise.sketch-pieces.title": "Oblik u malo segmenata",
  "exercise.sketch-pieces.task":
    "Nacrtajte zatvoreni oblik s barem jednim kutom (kap, list, kućica) koji prilagodba s tolerancijom 3 px sastavlja od najviše 6 Bézierovih segmenata.",
  "exercise.sketch-pieces.hint":
    "Vratite se na početak da se krivulja zatvori; crtajte mirno (drhtav potez treba više segmenata), napravite jedan oštar zaokret i držite toleranciju na 3 px ili više.",
  "exercise.sketch-pieces.notYet": "Još ne: {detail}.",
  "exercise.sketch-pieces.detail": "{pieces}, {corners}, {shape}",
  // ---- end sketch ----
};
