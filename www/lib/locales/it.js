/** The Italian (it) strings of the UI: every key of English (lib/strings.js). */
export default {
  "app.name": "splinelab",
  "app.galleryTitle": "{app} — {heading}",
  "app.demoTitle": "{title} — {app}",
  "app.tagline":
    "Curve parametriche da trascinare: ogni algoritmo del corso come figura interattiva.",
  "app.backToGallery": "← Tutte le demo",
  "app.loading": "Caricamento della libreria di curve…",
  "app.noSimd":
    "Questo browser non può eseguire la libreria di curve: richiede WebAssembly SIMD (Chrome o Edge 91, Firefox 89, Safari 16.4 o successivi).",
  "app.wasmFailed":
    "Impossibile caricare la libreria di curve ({message}). Esegui `make build`, poi ricarica.",
  "app.unknownDemo": "Non esiste una demo chiamata “{id}”. Mostro la galleria.",
  "app.footer": "Tutti i calcoli avvengono nel tuo browser (Rust compilato in WebAssembly).",
  "gallery.heading": "Demo, per sezione del programma",
  "gallery.open": "Apri la demo",
  "gallery.thumbnailAlt": "Anteprima di {title}",
  "section.1": "1 · Curve parametriche",
  "section.2": "2 · Curve di Bézier",
  "section.3": "3 · Curve B-spline",
  "section.4": "4 · Curve razionali e NURBS",
  "section.5": "5 · Curve di interpolazione",
  "section.6": "6 · Superfici",
  "toolbar.label": "Strumenti della demo",
  "toolbar.undo": "Annulla",
  "toolbar.undo.title": "Annulla (Ctrl+Z)",
  "toolbar.redo": "Ripeti",
  "toolbar.redo.title": "Ripeti (Ctrl+Shift+Z)",
  "toolbar.reset": "Reimposta",
  "toolbar.reset.title": "Torna alla figura iniziale",
  "toolbar.fit": "Adatta",
  "toolbar.fit.title":
    "Adatta la vista alla figura (trascina lo spazio vuoto per spostare, rotella o pizzico per lo zoom)",
  "toolbar.share": "Condividi link",
  "toolbar.share.title": "Copia un link che ripristina esattamente questa figura",
  "toolbar.svg": "SVG",
  "toolbar.svg.title": "Esporta la figura come SVG",
  "toolbar.tikz": "TikZ",
  "toolbar.tikz.title": "Esporta la figura come TikZ/PGF: un file .tex che pdflatex compila",
  "toolbar.png": "PNG",
  "toolbar.png.title": "Esporta la figura come PNG (2×, sfondo bianco)",
  "toolbar.json": "JSON",
  "toolbar.json.title": "Esporta lo stato come JSON",
  "toolbar.import": "Importa",
  "toolbar.import.title": "Carica uno stato da un file JSON",
  "toolbar.lecture": "Lezione",
  "toolbar.lecture.title": "Testo e tratti grandi per la proiezione",
  "toolbar.export": "Esporta:",
  "shell.controls": "Comandi",
  "shell.formula": "Formula",
  "shell.whatYouSee": "Cosa vedi",
  "shell.tryThis": "Prova",
  "shell.figureHelp3d":
    "Trascina un punto (nel piano rivolto verso di te), oppure premi Tab per selezionarne uno: i tasti freccia lo spostano (Shift: 10 px), PageUp/PageDown verso di te o lontano da te. Trascina lo spazio vuoto per ruotare, Shift+trascina, trascina con il tasto destro o due dita per spostare, rotella o pizzico per lo zoom; senza punto selezionato i tasti freccia ruotano la vista.",
  "shell.figureHelp3dTyped":
    "La curva segue le formule scritte nel pannello. Trascina per ruotare, Shift+trascina, trascina con il tasto destro o due dita per spostare, rotella o pizzico per lo zoom; i tasti freccia ruotano la vista.",
  "shell.figureHelp":
    "Trascina un punto, oppure premi Tab per selezionarne uno e i tasti freccia per spostarlo (Shift: 10 px). Trascina lo spazio vuoto per spostare la vista; rotella o pizzico per lo zoom.",
  "shell.figureHelpTyped":
    "La curva segue le formule scritte nel pannello. Trascina la figura per spostare la vista; rotella o pizzico per lo zoom.",
  "shell.openInPlayground": "Apri nell'area di prova",
  "handles.roleDescription": "figura interattiva",
  "handles.selected": "{label} selezionato, ({x}; {y})",
  "handles.moved": "{label} spostato in ({x}; {y})",
  "handles.selected3d": "{label} selezionato, ({x}; {y}; {z})",
  "handles.moved3d": "{label} spostato in ({x}; {y}; {z})",
  "scene3d.legend.gaussian": "curvatura gaussiana K",
  "scene3d.legend.mean": "curvatura media H",
  "status.linkCopied": "Link copiato negli appunti.",
  "status.linkShown": "Copia questo link: {url}",
  "status.imported": "Importato “{name}”.",
  "status.exported": "Salvato {name}.",
  "status.badLink": "Impossibile leggere questo link ({message}); la figura attuale resta.",
  "status.importTooLarge":
    "“{name}” pesa {size} MB; i file oltre {max} MB non vengono importati (uno stato è di pochi kilobyte).",
  "status.badImport": "Impossibile importare “{name}” ({message}); la figura attuale resta.",
  "status.rejected": "Modifica rifiutata: {message}",
  "status.nothingToUndo": "Niente da annullare.",
  "status.nothingToRedo": "Niente da ripetere.",
  "format.quoted": "“{value}”",
  "error.notObject": "lo stato deve essere un oggetto JSON",
  "error.unknownField": "campo sconosciuto “{field}”",
  "error.missingField": "manca il campo “{field}”",
  "error.notFinite": "il campo “{field}” deve essere un numero finito, ricevuto {value}",
  "error.notInteger": "il campo “{field}” deve essere un numero intero, ricevuto {value}",
  "error.range": "il campo “{field}” deve essere tra {min} e {max}, ricevuto {value}",
  "error.notBoolean": "il campo “{field}” deve essere true o false, ricevuto {value}",
  "error.notString": "il campo “{field}” deve essere uno tra {choices}, ricevuto {value}",
  "error.notArray": "il campo “{field}” deve essere una lista",
  "error.count": "il campo “{field}” deve avere tra {min} e {max} elementi, ricevuti {count}",
  "error.pointShape": "campo “{field}”: il punto {index} deve essere una coppia [x, y]",
  "error.pointShape3": "campo “{field}”: il punto {index} deve essere una terna [x, y, z]",
  "error.gridCount":
    "il campo “{field}” deve avere {rows} × {cols} = {expected} punti (righe lungo u), ricevuti {count}",
  "error.camera":
    "il campo “view” deve essere una camera [azimut, elevazione, distanza, x, y, z]: numeri finiti, distanza > 0, |elevazione| ≤ 89°",
  "error.pointFinite":
    "campo “{field}”: il punto {index} ha una coordinata che non è un numero finito",
  "error.knots": "campo “{field}”: {message}",
  "error.window":
    "il campo “view” deve essere quattro numeri finiti [xmin, ymin, xmax, ymax] con xmin < xmax e ymin < ymax",
  "error.badEncoding": "lo stato nel link non è valido (danneggiato o troncato)",
  "error.badJson": "JSON non valido: {message}",
  "error.version":
    "versione del file {version} non supportata (questa pagina legge la versione {expected})",
  "error.wrongDemo": "il file è per la demo “{found}”, non “{expected}”",
  "error.attribute": "attributo “{name}”: {message}",
  "error.recordShape":
    "“{value}” deve avere un testo per ciascuno di {fields}, separati da virgole",
  "error.unknownDemo": "non esiste una demo chiamata “{id}”",
  "control.t": "Parametro t",
  "control.t.input": "valore di t (decimale o frazione come 1/3)",
  "control.play": "Avvia",
  "control.pause": "Pausa",
  "control.stepBack": "Indietro",
  "control.stepForward": "Avanti",
  "control.stepBack.title": "t − 1/16",
  "control.stepForward.title": "t + 1/16",
  "control.addPoint": "Aggiungi punto",
  "control.addPoint.title": "Aggiungi un punto dopo quello selezionato (+)",
  "control.removePoint": "Rimuovi punto",
  "control.removePoint.title": "Rimuovi il punto selezionato (Canc)",
  "control.construction": "Mostra la costruzione",
  "control.badNumber": "“{value}” non è un numero",
  "curve.degree.1": "lineare",
  "curve.degree.2": "quadratica",
  "curve.degree.3": "cubica",
  "curve.degree.4": "quartica",
  "curve.degree.5": "quintica",
  "curve.degree.n": "di grado {n}",
  "deCasteljau.title": "Algoritmo di de Casteljau",
  "deCasteljau.summary":
    "L'interpolazione lineare ripetuta costruisce il punto P(t) di una curva di Bézier; ogni livello del triangolo è disegnato.",
  "deCasteljau.aria":
    "Curva di Bézier {kind} con {count} punti di controllo; t = {t}; punto P(t) = ({x}; {y})",
  "deCasteljau.degree": "Grado n = {n} ({count} punti di controllo)",
  "deCasteljau.tableCaption":
    "Il triangolo di de Casteljau per t = {t}: la riga r contiene i punti del livello r",
  "deCasteljau.tableLevel": "r = {r}",
  "deCasteljau.pointLabel": "P(t)",
  "deCasteljau.minPoints": "qui una curva di Bézier richiede almeno {min} punti di controllo",
  "deCasteljau.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "deCasteljau.whatYouSee":
    "Una curva di Bézier (blu) e il suo poligono di controllo (grigio, tratteggiato). Per il parametro t, ogni lato del poligono è diviso nel rapporto t : (1 − t); i nuovi punti (livello 1) formano un poligono più corto che viene diviso di nuovo, finché resta un solo punto: il punto P(t) sulla curva (vermiglio). La figura iniziale è l'esempio svolto delle dispense greche (sezione 2 del programma): P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2) per t = 1/4 dà P(t) = (29/16; 23/16).",
  "deCasteljau.try1":
    "Premi Avvia e osserva la costruzione scorrere lungo il poligono mentre P(t) traccia la curva.",
  "deCasteljau.try2":
    "Trascina P₂ e osserva quale parte della curva si muove di più: il peso di Bernstein di P₂ ha il massimo in t = 2/3.",
  "deCasteljau.try3":
    "Seleziona un punto con Tab e premi + per aggiungerne uno: il grado sale e il triangolo cresce di un livello.",
  "bernstein.title": "Base di Bernstein",
  "bernstein.summary":
    "I pesi dietro una curva di Bézier: ogni Bᵢⁿ(t) tracciata sotto la curva, con somma 1, ciascuna massima in t = i/n.",
  "bernstein.aria":
    "Curva di Bézier {kind} con {count} punti di controllo, e le sue {count} funzioni di base di Bernstein di grado {n} tracciate sotto; t = {t}; pesi {values} (somma {sum}); punto P(t) = ({x}; {y})",
  "bernstein.ariaPeak": "; {b} evidenziata: massima in t = {t}, dove la curva è in ({x}; {y})",
  "bernstein.degree": "Grado n = {n} ({count} punti di controllo, {count} funzioni di base)",
  "bernstein.pointLabel": "P(t)",
  "bernstein.peakPointLabel": "P({t})",
  "bernstein.peakLabel": "max in t = {t}",
  "bernstein.marker": "t = {t}",
  "bernstein.axisT": "t",
  "bernstein.axisValue0": "0",
  "bernstein.axisValue1": "1",
  "bernstein.formulaPeak": "massima in",
  "bernstein.tableCaption":
    "Pesi di Bernstein di grado {n} per t = {t} (passa sopra una riga o selezionala per evidenziare il suo punto di controllo)",
  "bernstein.colFunction": "Funzione di base",
  "bernstein.colValue": "Bᵢⁿ(t)",
  "bernstein.colMirror": "Bₙ₋ᵢⁿ(1 − t) (simmetria)",
  "bernstein.colPeak": "Massimo",
  "bernstein.rowName": "{b}, peso di {p}",
  "bernstein.peakCell": "{value} in t = {t}",
  "bernstein.sumRow": "Somma",
  "bernstein.sumNote": "Somma dei {count} pesi per t = {t}: {sum}",
  "bernstein.peakNote":
    "{b}, il peso di {p}, è massima in t = {t}: spostare {p} muove la curva soprattutto intorno a P({t}) = ({x}; {y}).",
  "bernstein.peakHint":
    "Passa sopra una funzione di base nel grafico o una riga della tabella, oppure seleziona un punto di controllo (Tab), per vedere dove agisce di più.",
  "bernstein.minPoints": "qui una curva di Bézier richiede almeno {min} punti di controllo",
  "bernstein.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "bernstein.whatYouSee":
    "Una curva di Bézier (blu) con il suo poligono di controllo e, sotto, i grafici delle sue funzioni di base di Bernstein Bᵢⁿ(t) su 0 ≤ t ≤ 1, ciascuno del colore dell'anello attorno al suo punto di controllo Pᵢ. Il punto P(t) (vermiglio) è la somma dei Pᵢ pesati con i valori in cui il marcatore interseca i grafici; questi pesi non sono mai negativi e hanno sempre somma 1. Bᵢⁿ ha un solo massimo, in t = i/n: è lì che spostare Pᵢ cambia di più la curva (banda evidenziata e P(i/n)). La figura iniziale è l'esempio svolto cubico delle dispense greche (sezione 2 del programma) per t = 1/4, con pesi 27/64, 27/64, 9/64, 1/64.",
  "bernstein.try1":
    "Passa sopra il grafico verde B₁³ (o seleziona P₁ con Tab): il suo massimo è in t = 1/3, e la banda sulla curva mostra dove P₁ attrae di più; ora trascina P₁ e osserva quella parte muoversi.",
  "bernstein.try2":
    "Trascina il marcatore nel grafico (o premi Avvia): i pesi cambiano, ma la riga Somma della tabella indica sempre 1. Confronta le due colonne centrali: Bᵢⁿ(t) è uguale a Bₙ₋ᵢⁿ(1 − t) (simmetria).",
  "bernstein.try3":
    "Premi + per aggiungere punti di controllo: i grafici diventano più stretti e più bassi, sempre con il massimo in i/n, quindi ogni punto agisce in modo più locale.",
  "subdivision.title": "Suddivisione",
  "subdivision.summary":
    "Dividi una curva di Bézier in t₀ in due curve di Bézier: i loro poligoni di controllo sono i lati del triangolo di de Casteljau; il dimezzamento ripetuto converge alla curva.",
  "subdivision.aria":
    "Curva di Bézier {kind} con {count} punti di controllo divisa in t₀ = {t} in un poligono sinistro L₀…L{n} e un poligono destro R₀…R{n}; punto di divisione ({x}; {y})",
  "subdivision.ariaLevels":
    "; suddivisione ripetuta in 1/2, livello {k}: {polygons} poligoni con {total} punti di controllo",
  "subdivision.control.t": "Dividi in t₀",
  "subdivision.control.t.input": "valore di t₀ (decimale o frazione come 1/3)",
  "subdivision.control.stepBack.title": "t₀ − 1/16",
  "subdivision.control.stepForward.title": "t₀ + 1/16",
  "subdivision.control.levels": "Dimezzamento ripetuto: livelli",
  "subdivision.control.levels.input": "Numero di livelli di suddivisione in 1/2 (da 0 a 6)",
  "subdivision.control.triangle": "Mostra il triangolo di de Casteljau",
  "subdivision.levelsNote":
    "Livello {k}: {polygons} poligoni, {total} punti di controllo ({distinct} distinti: i vicini condividono un estremo).",
  "subdivision.levelsNote0":
    "Livello 0: 1 poligono (quello della curva), {total} punti di controllo. Aumenta i livelli per dimezzare ripetutamente ogni pezzo in 1/2.",
  "subdivision.degree": "Grado n = {n} ({count} punti di controllo)",
  "subdivision.leftLabel": "L{i}",
  "subdivision.rightLabel": "R{i}",
  "subdivision.firstLabel": "{p} = {l}",
  "subdivision.lastLabel": "{p} = {r}",
  "subdivision.splitLabel": "{l} = {r}",
  "subdivision.splitPointLabel": "P(t₀)",
  "subdivision.formulaPolygons.many": "poligoni",
  "subdivision.formulaPolygons.one": "poligono",
  "subdivision.formulaPolygons.other": "poligoni",
  "subdivision.formulaPoints": "punti di controllo",
  "subdivision.tableCaption":
    "Punti di controllo delle due metà per t₀ = {t}: sinistra lᵢ (lato superiore del triangolo), destra rᵢ (ipotenusa)",
  "subdivision.colIndex": "i",
  "subdivision.colLeft": "Metà sinistra, su [0, t₀]",
  "subdivision.colRight": "Metà destra, su [t₀, 1]",
  "subdivision.minPoints": "qui una curva di Bézier richiede almeno {min} punti di controllo",
  "subdivision.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "subdivision.whatYouSee":
    "Una curva di Bézier (blu) tagliata in t₀ (punto vermiglio) in due curve di Bézier dello stesso grado. Il pezzo sinistro ha i punti di controllo L₀ … Lₙ (verdi, linea continua), il primo punto di ogni livello del triangolo di de Casteljau (il suo lato superiore); il pezzo destro ha R₀ … Rₙ (viola, tratteggiato, quadrati), l'ultimo punto di ogni livello (l'ipotenusa); il resto del triangolo è disegnato tenue. Con livelli sopra 0, ogni pezzo è dimezzato ancora e ancora in 1/2: dopo k livelli 2ᵏ piccoli poligoni aderiscono alla curva, ed è per questo che la suddivisione ripetuta converge a essa. La figura iniziale è l'esempio svolto cubico delle dispense greche (sezione 2 del programma); per t₀ = 1/4 le metà si incontrano in (29/16; 23/16).",
  "subdivision.try1":
    "Digita 1/4 per t₀: la tabella mostra i punti sinistri dell'esempio svolto (0; 0), (1/2; 1/2), (9/8; 1), (29/16; 23/16) e quelli destri (29/16; 23/16), (31/8; 11/4), (13/2; 7/2), (8; 2).",
  "subdivision.try2":
    "Porta i livelli a 3: otto poligoni, già vicini alla curva; a 5 o 6 è difficile distinguerli da essa.",
  "subdivision.try3":
    "Trascina t₀ verso 0: il poligono sinistro si riduce al punto P₀ mentre quello destro diventa l'originale.",
  "flattening.title": "Linearizzazione adattiva",
  "flattening.summary":
    "Una curva di Bézier disegnata come poligonale che resta entro una tolleranza ε: segmenti corti dove si piega, lunghi dove è dritta.",
  "flattening.tolerance": "Tolleranza ε (unità del mondo)",
  "flattening.tolerance.input": "tolleranza ε, da {min} a {max}",
  "flattening.badTolerance":
    "tolleranza ε: “{value}” non è un numero da {min} a {max}; resta il valore attuale",
  "flattening.flattenFailed": "impossibile calcolare la poligonale ({message}); mostro l'ultima",
  "flattening.band": "Mostra la banda di tolleranza (larghezza 2ε)",
  "flattening.presets": "Forme",
  "flattening.preset.title": "Sposta i quattro punti di controllo in questa forma",
  "flattening.preset.s": "Curva a S",
  "flattening.preset.loop": "Cappio",
  "flattening.preset.cusp": "Cuspide",
  "flattening.preset.straight": "Quasi dritta",
  "flattening.segments.many": "{count} segmenti",
  "flattening.segments.one": "{count} segmento",
  "flattening.segments.other": "{count} segmenti",
  "flattening.half": "Con ε/2 = {tolerance}: {count} segmenti (× {ratio}; √2 ≈ 1,41)",
  "flattening.countLabel": "{count} segmenti con ε = {tolerance}",
  "flattening.aria":
    "curva di Bézier cubica con punti di controllo {points}, linearizzata con tolleranza {tolerance}: una poligonale di {count} segmenti ({vertices} vertici); con tolleranza {half}: {halfCount} segmenti",
  "flattening.formula.whole": "curva intera:",
  "flattening.formula.flat": "piatta: un segmento",
  "flattening.formula.split": "dividi",
  "flattening.formula.until": "dividi finché ogni pezzo supera il test, poi disegna le corde:",
  "flattening.formula.segments": "segmenti",
  "flattening.whatYouSee":
    "La cubica blu è disegnata come la poligonale arancione che la libreria restituisce per la tolleranza ε: ogni punto della curva dista da essa meno di ε, quindi la curva non esce mai dalla banda grigia di larghezza 2ε. Il test è quello delle dispense greche (sezione 2 del programma, “disegno adattivo”): un pezzo è abbastanza piatto quando i suoi punti di controllo interni distano meno di ε dalla corda P₀P₃; altrimenti il pezzo viene accorciato e testato di nuovo (la libreria dimezza o raddoppia il passo del parametro di ogni pezzo finché il test non lo delimita, così servono pochi segmenti). Dove la curva si piega i pezzi sono corti, dove è quasi dritta basta una sola corda lunga, e dimezzare ε moltiplica il numero di segmenti per circa √2.",
  "flattening.try1":
    "Trascina il cursore della tolleranza da 1 fino a 0,001 e osserva i segmenti addensarsi dove la curva si piega di più.",
  "flattening.try2":
    "Premi “Cappio” e “Cuspide”: i segmenti corti si raccolgono sul cappio e sulla punta aguzza, mentre le estremità piatte ne ricevono di lunghi.",
  "flattening.try3":
    "Premi “Quasi dritta”, poi allontana P₁ dalla retta: il conteggio salta da pochi segmenti a molti.",
  "lineIntersection.title": "Intersezione curva–retta",
  "lineIntersection.summary":
    "I punti in cui una retta incontra una curva di Bézier, trovati dividendo la curva e scartando ogni riquadro che la retta non tocca.",
  "lineIntersection.handleA": "A",
  "lineIntersection.handleB": "B",
  "lineIntersection.sameLinePoints":
    "campo “line”: i due punti devono essere diversi, ricevuto ({x}; {y}) due volte",
  "lineIntersection.failed": "impossibile calcolare le intersezioni ({message}); mostro le ultime",
  "lineIntersection.depth": "Profondità di ricorsione mostrata",
  "lineIntersection.depth.input": "profondità, un numero intero da 0 a {max}",
  "lineIntersection.badDepth":
    "profondità: “{value}” non è un numero intero da 0 a {max}; resta la profondità attuale",
  "lineIntersection.shallower": "◀ Livello",
  "lineIntersection.shallower.title": "Mostra un livello in meno",
  "lineIntersection.deeper": "Livello ▶",
  "lineIntersection.deeper.title": "Mostra un livello in più",
  "lineIntersection.boxes":
    "Profondità {depth} di {deepest}. Riquadri visitati: {visited}; toccati dalla retta: {hit}; scartati: {pruned}. I riquadri smettono di dividersi sotto {tolerance}.",
  "lineIntersection.none": "nessuna intersezione",
  "lineIntersection.count.many": "{count} intersezioni",
  "lineIntersection.count.one": "1 intersezione",
  "lineIntersection.count.other": "{count} intersezioni",
  "lineIntersection.crossings":
    "La retta attraversa il poligono di controllo {polygon} volte e la curva {curve} volte: una retta non attraversa mai la curva più spesso del suo poligono (diminuzione della variazione).",
  "lineIntersection.rootLabel": "t = {t}",
  "lineIntersection.aria":
    "curva di Bézier cubica con punti di controllo {points} e la retta per A = {a} e B = {b}: {result}; la retta attraversa il poligono di controllo {polygon} volte; riquadri della ricorsione mostrati fino alla profondità {depth} di {deepest}",
  "lineIntersection.tableCaption":
    "Intersezioni, ordinate per t (ogni punto dista meno di {tolerance} dalla retta)",
  "lineIntersection.tableNone": "Nessuna intersezione: la retta non tocca la curva.",
  "lineIntersection.tableRoot": "radice",
  "lineIntersection.tablePoint": "P(t)",
  "lineIntersection.formula.miss": "lo stesso segno agli angoli del riquadro",
  "lineIntersection.formula.pruned": "la retta non tocca il riquadro: scartato",
  "lineIntersection.formula.until": ", finché il riquadro è sotto",
  "lineIntersection.formula.split": "altrimenti dividi in",
  "lineIntersection.formula.curve": "curva",
  "lineIntersection.formula.polygon": "poligono",
  "lineIntersection.whatYouSee":
    "Una cubica (blu) e la retta infinita per A e B (verde). La ricerca delle dispense greche (sezione 2 del programma): prendi il riquadro attorno ai punti di controllo; se la retta non lo tocca, nessuna parte della curva al suo interno può incontrare la retta e il riquadro viene scartato (grigio tenue); altrimenti dividi la curva in t = 1/2 e guarda entrambe le metà, finché i riquadri (contorni arancioni) sono più piccoli di 0,001. I punti vermigli sono le intersezioni che la libreria restituisce (raffinate fino a 10⁻⁹ dalla retta), etichettate con il loro t; come promette la proprietà di diminuzione della variazione, non sono mai più numerose degli attraversamenti del poligono di controllo.",
  "lineIntersection.try1":
    "Imposta la profondità a 0 e premi “Livello ▶” passo dopo passo: i riquadri lontani dalla retta escono, gli altri si stringono sui tre attraversamenti.",
  "lineIntersection.try2":
    "Trascina B verso l'alto finché la retta lascia la curva: il conteggio scende a 1, poi a “nessuna intersezione”, e il primo riquadro è già scartato.",
  "lineIntersection.try3":
    "Trascina P₁ e P₂ per appiattire il poligono di controllo: gli attraversamenti del poligono calano, e quelli della curva non li superano mai.",
  "joining.title": "Unione di due curve",
  "joining.summary":
    "Due pezzi di Bézier cubici si incontrano in una giunzione; una regola (C0, C1, G1, C2) li tiene uniti mentre trascini, e un verificatore indica la continuità.",
  "joining.aria":
    "Due pezzi di Bézier cubici, P per t in [0, 1] e Q per t in [1, 2]; regola {rule}; verificatore: {verdict}; P′(1) = {dp}, Q′(1) = {dq}",
  "joining.ruleLegend": "Regola nella giunzione",
  "joining.rule.none": "nessuna (trascina liberamente)",
  "joining.rule.C0": "C⁰: i pezzi si incontrano",
  "joining.rule.C1": "C¹: stessa velocità",
  "joining.rule.G1": "G¹: stessa retta tangente",
  "joining.rule.C2": "C²: anche stessa accelerazione",
  "joining.checkerLegend": "Il verificatore di continuità",
  "joining.verdict": "{c}, {g} nella giunzione",
  "joining.verdict.broken": "nemmeno C⁰: i pezzi non si incontrano",
  "joining.verdict.infinite": "C∞: un unico polinomio",
  "joining.legend.none":
    "Nessun vincolo: ogni punto si muove per conto suo, e il verificatore indica ciò che la giunzione è diventata.",
  "joining.legend.C0":
    "Il quadrato segna il punto fissato dalla regola: Q₀ = P₃. Trascinalo e P₃ lo segue.",
  "joining.legend.C1":
    "I quadrati segnano i punti fissati dalla regola: Q₀ = P₃ e Q₁ = 2P₃ − P₂ (P₂ riflesso nella giunzione). Trascina un quadrato e a seguirlo sarà invece il pezzo sinistro.",
  "joining.legend.G1":
    "I quadrati segnano i punti fissati dalla regola: Q₀ = P₃, e Q₁ sulla semiretta da P₂ attraverso P₃. Q₁ scorre solo lungo quella retta: la sua distanza è libera, quindi la velocità può saltare.",
  "joining.legend.C2":
    "I quadrati segnano i punti fissati dalla regola: Q₀, Q₁ e Q₂ = P₁ − 4P₂ + 4P₃. I lati P₁P₂ e Q₂Q₁ prolungati si incontrano in un punto D (la struttura ad A).",
  "joining.free.none": "Liberi: tutti gli otto punti.",
  "joining.free.C0": "Liberi: P₀, P₁, P₂, Q₁, Q₂, Q₃ e la giunzione.",
  "joining.free.C1": "Liberi: P₀, P₁, Q₂, Q₃, la giunzione e uno tra P₂, Q₁.",
  "joining.free.G1": "Liberi: P₀, P₁, P₂, Q₂, Q₃, la giunzione e la lunghezza di Q₀Q₁.",
  "joining.free.C2":
    "Per due cubiche C² lascia quasi liberi solo P₀ e Q₃: P₁, P₂ e la giunzione fissano Q₁ e Q₂.",
  "joining.leftArrow": "P′(1)",
  "joining.rightArrow": "Q′(1)",
  "joining.pointD": "D",
  "joining.arrowCaption":
    "Frecce: velocità P′(1) in arrivo e Q′(1) in uscita dalla giunzione, disegnate a 1/6 della lunghezza",
  "joining.tableCaption":
    "Nella giunzione t = 1 (derivate dal nucleo di calcolo, P su [0, 1], Q su [1, 2])",
  "joining.row.p3-p2": "P₃ − P₂",
  "joining.row.q1-q0": "Q₁ − Q₀",
  "joining.row.dp": "P′(1)",
  "joining.row.dq": "Q′(1)",
  "joining.row.ddp": "P″(1)",
  "joining.row.ddq": "Q″(1)",
  "joining.formula.none":
    "Nessuna regola: il verificatore confronta P(1), P′(1), P″(1) con Q(1), Q′(1), Q″(1)",
  "joining.formula.rule": "regola:",
  "joining.formula.anyLength": "lunghezza qualsiasi",
  "joining.formula.notG1": "le direzioni tangenti differiscono (o i pezzi non si incontrano)",
  "joining.formula.checker": "verificatore:",
  "joining.formula.notC0": "non C⁰",
  "joining.whatYouSee":
    "Due pezzi di Bézier cubici: P (blu) per t ∈ [0, 1] e Q (verde) per t ∈ [1, 2], uniti in P₃ = Q₀. La regola scelta dalla sezione 2 del programma (le dispense greche) viene mantenuta mentre trascini: i punti che fissa (quadrati) seguono, e il verificatore di continuità della sezione 1 indica cosa è davvero la giunzione. Le due frecce sono le velocità in arrivo e in uscita dalla giunzione: per C¹ sono uguali, per G¹ puntano solo nella stessa direzione. Per due cubiche C² lascia quasi liberi solo P₀ e Q₃.",
  "joining.try1":
    "Con C¹, trascina P₂ e osserva Q₁ rifletterlo attraverso la giunzione; poi scegli G¹ e fai scorrere Q₁ lungo la linea tratteggiata: il verificatore scende a C⁰, G¹ quando le frecce assumono lunghezze diverse.",
  "joining.try2":
    "Scegli “nessuna” e allontana il Q₀ della giunzione da P₃: il verificatore indica che i pezzi non si incontrano nemmeno.",
  "joining.try3":
    "Scegli C² e trascina P₁: Q₂ si muove con esso attraverso il punto D della struttura ad A, e solo P₀ e Q₃ restano dove li metti.",
  "bezierProperties.title": "Proprietà delle curve di Bézier",
  "bezierProperties.summary":
    "Inviluppo convesso, invarianza affine, simmetria, elevazione del grado e diminuzione della variazione, ciascuna mostrata su una curva trascinabile.",
  "bezierProperties.propertyLegend": "Proprietà",
  "bezierProperties.property.hull": "Inviluppo convesso",
  "bezierProperties.property.affine": "Trasformazione affine",
  "bezierProperties.property.reversed": "Ordine inverso (simmetria)",
  "bezierProperties.property.elevation": "Elevazione del grado",
  "bezierProperties.property.variation": "Diminuzione della variazione",
  "bezierProperties.affineLegend": "La trasformazione affine (attorno al baricentro c)",
  "bezierProperties.rotation": "Rotazione (gradi)",
  "bezierProperties.rotation.input": "rotazione in gradi",
  "bezierProperties.scale": "Scala",
  "bezierProperties.scale.input": "fattore di scala",
  "bezierProperties.shear": "Taglio (x += k·y)",
  "bezierProperties.shear.input": "fattore di taglio k",
  "bezierProperties.elevationLegend": "Elevazione del grado",
  "bezierProperties.elevations": "Elevazioni",
  "bezierProperties.elevations.input": "numero di elevazioni (da 0 a 8)",
  "bezierProperties.lineA": "A",
  "bezierProperties.lineB": "B",
  "bezierProperties.lineDegenerate": "campo “line”: i suoi due punti devono essere diversi",
  "bezierProperties.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "bezierProperties.minPoints": "qui una curva di Bézier richiede almeno {min} punti di controllo",
  "bezierProperties.degree": "Grado n = {n} ({count} punti di controllo)",
  "bezierProperties.note.hull":
    "La regione grigia è l'inviluppo convesso dei punti di controllo: ogni punto della curva ne è una media pesata, con pesi ≥ 0 a somma 1.",
  "bezierProperties.note.affine":
    "Verde: la curva dei punti di controllo trasformati (costruita dal nucleo di calcolo). Punti rossi: punti della curva blu trasformati uno per uno con la stessa matrice. Giacciono sulla curva verde.",
  "bezierProperties.note.reversed":
    "Arancione, tratteggiata: la curva dei punti di controllo in ordine inverso Pₙ … P₀. Stessi punti, verso opposto (le frecce).",
  "bezierProperties.note.elevation":
    "Arancione: il poligono di controllo dopo le elevazioni. Stessa curva, un punto in più per elevazione; il poligono si avvicina alla curva.",
  "bezierProperties.note.variation":
    "Trascina A e B per spostare la retta: non attraversa mai la curva più spesso di quanto attraversi il poligono di controllo.",
  "bezierProperties.readout.hull": "Inviluppo: {k} vertici ({names})",
  "bezierProperties.readout.affine": "Scarto massimo: {d}",
  "bezierProperties.readout.reversed": "Scarto massimo: {d}",
  "bezierProperties.readout.elevation": "{count} punti di controllo ({n} + {e})",
  "bezierProperties.readout.variation":
    "La retta attraversa il poligono {k} volte, la curva {j} volte",
  "bezierProperties.formula.sum": "somma",
  "bezierProperties.formula.hullVertices": "vertici dell'inviluppo",
  "bezierProperties.formula.because": "perché",
  "bezierProperties.formula.samples": "campioni",
  "bezierProperties.formula.forExample": "es.",
  "bezierProperties.formula.points": "punti di controllo",
  "bezierProperties.formula.lineCurve": "retta ∩ curva",
  "bezierProperties.formula.linePolygon": "retta ∩ poligono",
  "bezierProperties.tableCaption":
    "Dopo un'elevazione: grado {n} → {m}, punti di controllo Q₀ … Q{last}",
  "bezierProperties.aria.hull":
    "Curva di Bézier {kind} dentro l'inviluppo convesso dei suoi punti di controllo ({k} vertici dell'inviluppo)",
  "bezierProperties.aria.affine":
    "Curva di Bézier {kind} e la sua immagine con rotazione {rotation}°, scala {scale}, taglio {shear}; i punti trasformati della curva giacciono sulla curva trasformata (scarto massimo {d})",
  "bezierProperties.aria.reversed":
    "Curva di Bézier {kind} e la curva dei suoi punti di controllo invertiti disegnata tratteggiata sopra (scarto massimo {d})",
  "bezierProperties.aria.elevation":
    "Curva di Bézier {kind} elevata {e} volte: {count} punti di controllo, stessa curva",
  "bezierProperties.aria.variation":
    "Curva di Bézier {kind} e una retta: la retta attraversa il poligono di controllo {k} volte e la curva {j} volte",
  "bezierProperties.whatYouSee":
    "Una curva di Bézier (blu) e, una alla volta, le proprietà elencate nella sezione 2 del programma (dalle dispense greche): resta dentro l'inviluppo convesso dei suoi punti di controllo; trasformare i punti di controllo con una trasformazione affine trasforma l'intera curva; i punti in ordine inverso danno la stessa curva percorsa all'indietro; l'elevazione del grado aggiunge un punto di controllo senza cambiare la curva; e una retta non attraversa la curva più spesso del poligono di controllo. Si parte dall'esempio svolto P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2).",
  "bezierProperties.try1":
    "Scegli “Trasformazione affine” e muovi il cursore del taglio: i punti rossi (punti della curva trasformati) restano sulla curva verde (costruita dai punti di controllo trasformati).",
  "bezierProperties.try2":
    "Scegli “Elevazione del grado” e porta il numero a 8: il poligono arancione ha 12 punti e aderisce alla curva.",
  "bezierProperties.try3":
    "Scegli “Diminuzione della variazione” e trascina A e B in modo che la retta tagli il poligono il più spesso possibile: la curva è attraversata al massimo altrettante volte.",
  "derivatives.title": "Derivate e curvatura",
  "derivatives.summary":
    "La velocità P′(t), la normale, il cerchio osculatore e la curvatura con segno di una curva di Bézier, con il suo odografo accanto.",
  "derivatives.aria":
    "Curva di Bézier {kind}; t = {t}; P(t) = ({x}; {y}); velocità P′(t) = ({dx}; {dy}); curvatura κ = {kappa}; l'odografo è disegnato a destra",
  "derivatives.originLabel": "origine O",
  "derivatives.pointLabel": "P(t)",
  "derivatives.velocityLabel": "P′(t)",
  "derivatives.normalLabel": "N",
  "derivatives.straight": "Dritta qui (κ ≈ 0): nessun cerchio osculatore",
  "derivatives.cusp": "Cuspide: P′(t) = 0, la curvatura è infinita",
  "derivatives.cuspShort": "una cuspide",
  "derivatives.hodographCaption": "Odografo P′(t) (grado {m}), origine O",
  "derivatives.scaleCaption": "Frecce di velocità e odografo disegnati in scala 1/{n}",
  "derivatives.curvatureLegend": "Curvatura in t",
  "derivatives.readout": "κ(t) = {kappa}",
  "derivatives.radius":
    "Cerchio osculatore di raggio {r}, centro a {side} della direzione di percorrenza",
  "derivatives.left": "sinistra (κ > 0: gira in senso antiorario)",
  "derivatives.right": "destra (κ < 0: gira in senso orario)",
  "derivatives.length": "Lunghezza d'arco L = {length}",
  "derivatives.degree": "Grado n = {n} ({count} punti di controllo)",
  "derivatives.minPoints":
    "questa demo richiede almeno {min} punti di controllo (una quadratica o superiore)",
  "derivatives.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "derivatives.tableCaption":
    "Derivate dal nucleo di calcolo per t = {t}, e i punti di controllo dell'odografo",
  "derivatives.row.point": "P(t)",
  "derivatives.row.dp": "P′(t)",
  "derivatives.row.ddp": "P″(t)",
  "derivatives.row.kappa": "κ(t)",
  "derivatives.row.radius": "raggio 1/|κ|",
  "derivatives.row.dp0": "P′(0)",
  "derivatives.row.dp1": "P′(1)",
  "derivatives.row.length": "lunghezza d'arco",
  "derivatives.row.hodograph": "H{i} = {label}",
  "derivatives.whatYouSee":
    "Una curva di Bézier (blu) con il punto P(t), la sua velocità P′(t) (freccia vermiglia), la normale unitaria N e il cerchio osculatore (arancione), il cerchio che aderisce alla curva in P(t), di raggio 1/|κ|. A destra c'è l'odografo (verde, sezione 2 del programma, dalle dispense greche): la curva tracciata dalla velocità, una curva di Bézier di un grado in meno i cui punti di controllo sono n(P₁ − P₀), n(P₂ − P₁), …; la freccia dalla sua origine O è lo stesso vettore P′(t). Si parte dall'esempio svolto P₀ = (0; 0), P₁ = (2; 2), P₂ = (6; 4), P₃ = (8; 2).",
  "derivatives.try1":
    "Imposta t a 0 e poi a 1: la velocità è 3(P₁ − P₀) = (6; 6) all'inizio e 3(P₃ − P₂) = (6; −6) alla fine — il primo e l'ultimo lato del poligono dell'odografo.",
  "derivatives.try2":
    "Trascina P₂ sotto la retta P₀P₃: la curva gira dall'altra parte, κ cambia segno e il cerchio salta dall'altro lato.",
  "derivatives.try3":
    "Premi Avvia e osserva la freccia dell'odografo scorrere lungo la sua curva mentre la freccia tangente percorre la curva: sono sempre lo stesso vettore.",
  "knotRuler.selected": "nodo {label} selezionato, {u}",
  "knotRuler.moved": "nodo {label} spostato in {u}",
  "knotRuler.valueMultiple": "{u} (×{r})",
  "knotRuler.break": "rottura",
  "knotRuler.domain": "dominio [u{p}, u{n1}] = [{a}; {b}]",
  "bsplineBasis.title": "Funzioni di base B-spline",
  "bsplineBasis.summary":
    "Ogni Nᵢ,ₚ dalla ricorrenza di Cox–de Boor, tracciata sotto la curva sopra un righello dei nodi trascinabile: supporto locale, somma 1, e il triangolo dei valori in u.",
  "bsplineBasis.aria":
    "B-spline {kind} con {count} punti di controllo e nodi [{knots}]; in u = {u} (intervallo [{a}; {b})) le funzioni di base non nulle sono {values}, somma {sum}; punto C(u) = ({x}; {y}); tutte le funzioni di base sono tracciate sotto la curva, sopra il righello dei nodi",
  "bsplineBasis.ariaContinuity": "; continuità nei nodi interni: {list}",
  "bsplineBasis.ariaSupport": "; {name} evidenziata: supporto [{a}; {b})",
  "bsplineBasis.degreeLegend": "Grado p",
  "bsplineBasis.degreeOption": "{p}",
  "bsplineBasis.control.u": "Parametro u",
  "bsplineBasis.control.u.input": "valore di u nel dominio (decimale o frazione come 5/2)",
  "bsplineBasis.sumNote": "Σ Nᵢ,ₚ({u}) = {sum}",
  "bsplineBasis.knotNote":
    "{count} punti di controllo, grado p = {p}: {m} nodi u₀ … u{last} (m + 1 = n + p + 2). Cambiare il grado o il numero di punti riporta i nodi al vettore uniforme vincolato agli estremi (clamped).",
  "bsplineBasis.resetKnots": "Nodi uniformi vincolati",
  "bsplineBasis.resetKnots.title":
    "Sostituisci i nodi con p + 1 nodi uguali agli estremi e nodi interni equidistanti",
  "bsplineBasis.rulerHelp":
    "Righello dei nodi (sotto il grafico): trascina un nodo — non può superare i vicini; fai doppio clic o premi Invio per fondere su di esso il nodo successivo; Canc separa una pila. Con Tab oltre l'ultimo punto di controllo selezioni i nodi.",
  "bsplineBasis.minPoints":
    "una B-spline di grado {degree} richiede almeno {min} punti di controllo",
  "bsplineBasis.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "bsplineBasis.fewPoints":
    "campo “points”: una B-spline di grado {p} richiede almeno {need} punti di controllo, ricevuti {count}",
  "bsplineBasis.uRange": "il campo “u” deve stare nel dominio [{a}; {b}], ricevuto {u}",
  "bsplineBasis.multiplicity.max": "u{i} ha già la molteplicità massima, p + 1 = {max}",
  "bsplineBasis.multiplicity.ends": "non resta alcun nodo interno da fondere su u{i}",
  "bsplineBasis.multiplicity.single": "u{i} è un nodo semplice: niente da separare",
  "bsplineBasis.pointLabel": "C(u)",
  "bsplineBasis.marker": "u = {u}",
  "bsplineBasis.axisValue0": "0",
  "bsplineBasis.axisValue1": "1",
  "bsplineBasis.axisU": "u",
  "bsplineBasis.formulaOtherwise": "altrimenti",
  "bsplineBasis.tableCaption":
    "Funzioni di base di grado {p} in u = {u} (passa sopra una riga o selezionala per evidenziarne il supporto)",
  "bsplineBasis.colFunction": "Funzione di base",
  "bsplineBasis.colSupport": "Supporto [uᵢ, uᵢ₊ₚ₊₁)",
  "bsplineBasis.colValue": "Nᵢ,ₚ(u)",
  "bsplineBasis.rowName": "{name}, peso di {point}",
  "bsplineBasis.supportCell": "[u{i}, u{j}) = [{a}; {b})",
  "bsplineBasis.sumRow": "Somma",
  "bsplineBasis.triangleCaption":
    "Triangolo di Cox–de Boor in u = {u}: intervallo k = {k}, [u{kSub}, u{k1Sub}) = [{a}; {b}); la riga r contiene i valori di grado r per i = k − r … k, ciascuno ottenuto dai due sopra",
  "bsplineBasis.triangleCorner": "grado r",
  "bsplineBasis.triangleRow": "r = {r}",
  "bsplineBasis.whatYouSee":
    "Una curva B-spline (blu) sopra il suo poligono di controllo; sotto, i grafici delle sue funzioni di base Nᵢ,ₚ(u), ciascuno del colore dell'anello attorno al suo punto di controllo Pᵢ; sotto il grafico, il righello dei nodi con i nodi u₀ … u_m e il dominio [uₚ, uₙ₊₁] (barra blu). Il punto C(u) è la somma dei Pᵢ pesati con i valori in cui il marcatore interseca i grafici: al più p + 1 sono non nulli (p + 1 è l'ordine m = p + 1 delle dispense italiane) e hanno sempre somma 1. Ogni Nᵢ,ₚ è nulla fuori dal suo supporto [uᵢ, uᵢ₊ₚ₊₁), quindi Pᵢ muove solo quel pezzo di curva. Si parte dall'esempio quadratico delle dispense croate (sezione 3 del programma): U = [0, 0, 0, 1, 2, 3, 4, 4, 4], dove in u = 5/2 i valori sono 1/8, 3/4, 1/8 — lì N₃,₂ = (−2u² + 10u − 11)/2 (le dispense riportano per errore +11).",
  "bsplineBasis.try1":
    "Passa sopra il grafico viola N₂,₂ (o seleziona P₂ con Tab): il suo supporto [0, 3) è ombreggiato, e trascinare P₂ muove solo quella parte della curva.",
  "bsplineBasis.try2":
    "Trascina u₄ (il nodo in 2) sul righello verso u₅: i grafici attorno si allungano e si stringono, si ferma a 3, e l'etichetta sopra passa da C¹ a C⁰ quando i due nodi si incontrano — oppure fai doppio clic su u₄ per fonderli in un colpo.",
  "bsplineBasis.try3":
    "Scegli il grado 3: i nodi diventano [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], ogni grafico si allarga a quattro intervalli e il triangolo cresce di una riga — la somma indica sempre 1.",
  "deBoor.title": "Algoritmo di de Boor",
  "deBoor.summary":
    "L'interpolazione ripetuta dei p + 1 punti di controllo attivi costruisce il punto C(u) di una B-spline; i nodi decidono ogni rapporto α.",
  "deBoor.aria":
    "B-spline {kind} con {count} punti di controllo, nodi {knots}; u = {u} nell'intervallo k = {k}, [{uk}; {uk1}); punto C(u) = ({x}; {y})",
  "deBoor.degree": "Grado p = {p}, {count} punti di controllo, {segments}",
  "deBoor.spans.many": "{count} intervalli non vuoti",
  "deBoor.spans.one": "{count} intervallo non vuoto",
  "deBoor.spans.other": "{count} intervalli non vuoti",
  "deBoor.span": "k = {k}: u ∈ [u{ks}, u{ks1}) = [{uk}; {uk1})",
  "deBoor.spanCaption": "intervallo [u{k}, u{k1})",
  "deBoor.uCaption": "u = {u}",
  "deBoor.multiplicity": "×{r}",
  "deBoor.tableCaption":
    "Il triangolo di de Boor in u = {u} (intervallo k = {k}): la riga r contiene dⱼʳ, j = r … p, con l'α del suo passo",
  "deBoor.tableLevel": "r = {r}",
  "deBoor.alphaCell": "α = {value}",
  "deBoor.pointLabel": "C(u)",
  "deBoor.control.u": "Parametro u",
  "deBoor.control.u.input": "valore di u (decimale o frazione come 3/2)",
  "deBoor.control.stepBack.title": "u − 1/16 del dominio",
  "deBoor.control.stepForward.title": "u + 1/16 del dominio",
  "deBoor.control.degree": "Grado p",
  "deBoor.control.degree.input": "grado p (da 1 a 5)",
  "deBoor.control.knots": "Vettore dei nodi U (digita e premi Invio)",
  "deBoor.knotsHelp":
    "{m} nodi non decrescenti per {count} punti di grado {p} (m + 1 = n + p + 2).",
  "deBoor.control.clamped": "Nodi uniformi vincolati",
  "deBoor.control.clamped.title": "p + 1 nodi uguali a ogni estremo, 1, 2, … in mezzo",
  "deBoor.control.addPoint.title":
    "Aggiungi un punto dopo quello selezionato (+); i nodi diventano uniformi vincolati",
  "deBoor.control.removePoint.title":
    "Rimuovi il punto selezionato (Canc); i nodi diventano uniformi vincolati",
  "deBoor.knotsReset":
    "Il vettore dei nodi è stato riportato a uniforme vincolato per i nuovi punti o il nuovo grado.",
  "deBoor.degreeRange": "il grado deve essere un numero intero da 1 a {max}, ricevuto “{value}”",
  "deBoor.minPoints": "qui una B-spline richiede almeno {min} punti di controllo",
  "deBoor.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "deBoor.error.degree":
    "il campo “degree” vale {p}, ma {count} punti di controllo consentono al massimo il grado {count} − 1",
  "deBoor.error.knotCount":
    "il campo “knots” deve avere n + p + 2 = {expected} elementi per {count} punti di grado {p}, ricevuti {got}",
  "deBoor.error.knotOrder":
    "il campo “knots” non deve decrescere: l'elemento {index} vale {value} dopo {previous}",
  "deBoor.error.multiplicity": "campo “knots”: il nodo {value} compare più di p + 1 = {max} volte",
  "deBoor.error.domain": "campo “knots”: il dominio [u{p}, u{n1}] = [{a}; {b}] è vuoto",
  "deBoor.whatYouSee":
    "Il poligono grigio tratteggiato contiene tutti i punti di controllo; solo i p + 1 attivi dell'intervallo che contiene u (grigio continuo) partecipano. Ogni livello colorato interpola il precedente con il proprio rapporto α, letto dal vettore dei nodi, finché resta un solo punto C(u) — l'algoritmo di de Boor della sezione 3 del programma (la convenzione delle dispense croate e italiane). Con i nodi 0 0 0 0 1 1 1 1 ogni α è uguale a u ed è la costruzione di de Casteljau.",
  "deBoor.try1":
    "Premi Avvia e osserva i punti attivi saltare quando u attraversa un nodo sulla striscia sotto la figura.",
  "deBoor.try2":
    "Rimuovi punti finché ne restano quattro, poi digita i nodi 0 0 0 0 1 1 1 1 e u = 1/4: ogni α vale 1/4 e il triangolo è quello di de Casteljau (per P₀ … P₃ = (0; 0), (2; 2), (6; 4), (8; 2) termina in (29/16; 23/16)).",
  "deBoor.try3":
    "Digita un nodo interno ripetuto, es. 0 0 0 0 1 2 2 4 4 4 4: alcuni α diventano 0 o 1 e la curva passa più vicino a un punto di controllo.",
  "knotVectors.title": "Tipi di vettore dei nodi",
  "knotVectors.summary":
    "Un poligono di controllo, tre vettori dei nodi: le curve vincolate agli estremi (clamped) partono da P₀, quelle non vincolate no, quelle chiuse si richiudono in modo regolare.",
  "knotVectors.aria":
    "B-spline {kind} su {count} punti di controllo: nodi vincolati {clamped}, la curva vincolata parte da {c0}; la curva uniforme non vincolata parte da {u0}; P₀ = {p0}; una curva chiusa percorre il ciclo dei punti",
  "knotVectors.degree": "Grado p = {p}, {count} punti di controllo",
  "knotVectors.degreeRange":
    "il grado deve essere un numero intero da 1 a {max}, ricevuto “{value}”",
  "knotVectors.minPoints": "qui una B-spline richiede almeno {min} punti di controllo",
  "knotVectors.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "knotVectors.error.degree":
    "il campo “degree” vale {p}, ma {count} punti di controllo consentono al massimo il grado {count} − 1",
  "knotVectors.control.degree": "Grado p",
  "knotVectors.control.degree.input": "grado p (da 1 a 5)",
  "knotVectors.control.spacing": "Nodi interni del vettore vincolato",
  "knotVectors.control.show": "Curve mostrate",
  "knotVectors.spacing.uniform": "uniforme: 1, 2, …, n − p",
  "knotVectors.spacing.chord": "lunghezza di corda: somme di |Pᵢ₊₁ − Pᵢ|",
  "knotVectors.spacing.centripetal": "centripeta: somme di √|Pᵢ₊₁ − Pᵢ|",
  "knotVectors.show.clamped": "Vincolata agli estremi (clamped) — blu continua",
  "knotVectors.show.unclamped": "Uniforme non vincolata — verde tratteggiata",
  "knotVectors.show.closed": "Chiusa (periodica) — viola punteggiata",
  "knotVectors.legend.clamped": "vincolata agli estremi (clamped)",
  "knotVectors.legend.clamped.uniform": "vincolata uniforme",
  "knotVectors.legend.clamped.chord": "vincolata, spaziatura a lunghezza di corda",
  "knotVectors.legend.clamped.centripetal": "vincolata, spaziatura centripeta",
  "knotVectors.legend.unclamped": "uniforme non vincolata",
  "knotVectors.legend.closed": "chiusa (periodica)",
  "knotVectors.style.clamped": "continua",
  "knotVectors.style.unclamped": "tratteggiata",
  "knotVectors.style.closed": "punteggiata",
  "knotVectors.column.curve": "Curva",
  "knotVectors.column.knots": "Vettore dei nodi u₀ … uₘ",
  "knotVectors.column.domain": "Dominio [uₚ, uₙ₊₁]",
  "knotVectors.column.start": "Inizio C(uₚ)",
  "knotVectors.column.end": "Fine C(uₙ₊₁)",
  "knotVectors.tableCaption":
    "I vettori dei nodi, come li costruisce il nucleo di calcolo, e dove ogni curva inizia e finisce",
  "knotVectors.tex.clamped": "vincolata",
  "knotVectors.tex.chord": "corda",
  "knotVectors.tex.centripetal": "centripeta",
  "knotVectors.tex.unclamped": "non vincolata",
  "knotVectors.tex.closed": "chiusa",
  "knotVectors.tex.domain": "dominio",
  "knotVectors.tex.seam": "nella cucitura",
  "knotVectors.tex.lastRepeated": "l'ultimo p + 1 volte",
  "knotVectors.tex.legs": "termini:",
  "knotVectors.whatYouSee":
    "Gli stessi punti di controllo portano tre B-spline dello stesso grado. I nodi vincolati agli estremi (clamped) ripetono i valori estremi p + 1 volte, così quella curva parte da P₀ e finisce in Pₙ; nodi equidistanti non vincolati danno una curva che inizia e finisce dentro il poligono; la curva chiusa ripete i primi p punti dopo l'ultimo, così si richiude con la piena continuità C^(p−1) nella cucitura (sugli intervalli dove usa gli stessi punti della curva non vincolata le due coincidono: punti sopra trattini). La spaziatura a lunghezza di corda e quella centripeta spostano i nodi interni in proporzione ai lati del poligono — sezione 3 del programma, dalle dispense greche e croate.",
  "knotVectors.try1":
    "Imposta il grado a 1: ogni curva diventa il poligono (quella chiusa con il lato di chiusura); portalo a 5 e osserva la curva non vincolata e quella chiusa rimpicciolirsi dentro il poligono.",
  "knotVectors.try2":
    "Scegli la lunghezza di corda e trascina P₂ lontano: i nodi interni nella tabella crescono con i lati vicini.",
  "knotVectors.try3":
    "Trascina P₀: l'inizio della curva vincolata lo segue esattamente, quello della curva non vincolata si sposta solo di un sesto del trascinamento (per una cubica).",
  "localControl.title": "Controllo locale e inviluppo convesso forte",
  "localControl.summary":
    "Spostare un punto di controllo di una B-spline cambia solo p + 1 intervalli; ogni intervallo resta dentro l'inviluppo dei suoi p + 1 punti attivi.",
  "localControl.control.u": "Parametro u",
  "localControl.control.u.input": "valore di u (decimale o frazione come 5/2)",
  "localControl.control.point": "Evidenzia il raggio d'azione di Pᵢ, i =",
  "localControl.control.point.input": "indice i del punto di cui è mostrato il raggio d'azione",
  "localControl.control.degree": "Grado p",
  "localControl.control.degree.input": "grado p (da 1 a 5)",
  "localControl.error.tooFewPoints":
    "campo “points”: il grado {p} richiede almeno {min} punti di controllo, ricevuti {count}",
  "localControl.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "localControl.pointLabel": "C(u)",
  "localControl.formula.only": "solo questa parte si muove con",
  "localControl.formula.vertices.many": "vertici dell'inviluppo",
  "localControl.formula.vertices.one": "vertice dell'inviluppo",
  "localControl.formula.vertices.other": "vertici dell'inviluppo",
  "localControl.readout.span": "Intervallo k = {k}: {names}",
  "localControl.readout.hull.many":
    "Solo questi p + 1 punti hanno qui Nᵢ,ₚ(u) ≠ 0; il loro inviluppo (ombreggiato, {count} vertici) contiene tutto questo pezzo di curva.",
  "localControl.readout.hull.one":
    "Solo questi p + 1 punti hanno qui Nᵢ,ₚ(u) ≠ 0; il loro inviluppo (ombreggiato, {count} vertice) contiene tutto questo pezzo di curva.",
  "localControl.readout.hull.other":
    "Solo questi p + 1 punti hanno qui Nᵢ,ₚ(u) ≠ 0; il loro inviluppo (ombreggiato, {count} vertici) contiene tutto questo pezzo di curva.",
  "localControl.readout.support":
    "Spostare {name} cambia C(u) solo per u in [{lo}; {hi}; il resto della curva resta fermo.",
  "localControl.aria":
    "B-spline {kind} vincolata con {count} punti di controllo; {name} muove solo la parte per u in [{lo}; {hi}; u = {u} sta nell'intervallo {k}, punti attivi {names}, inviluppo con {hull}; punto C(u) = ({x}; {y})",
  "localControl.vertices.many": "{count} vertici",
  "localControl.vertices.one": "{count} vertice",
  "localControl.vertices.other": "{count} vertici",
  "localControl.tableCaption":
    "Ogni funzione di base in u = {u} (grado {p}): solo le p + 1 righe evidenziate sono non nulle",
  "localControl.table.point": "punto",
  "localControl.table.value": "Nᵢ,{p}(u)",
  "localControl.table.support": "non nulla per u in",
  "localControl.whatYouSee":
    "Una B-spline cubica vincolata agli estremi (blu), il suo poligono di controllo (grigio, tratteggiato) e, sotto la figura, i suoi nodi come tacche sulla retta del parametro. La banda colorata segna la parte di curva che il punto cerchiato P_i può muovere: i parametri [u_i, u_{i+p+1}) in cui la sua funzione di base N_i,p non è zero; fuori da lì la curva non si muove affatto (controllo locale, sezione 3 del programma; le dispense croate: spostare un punto cambia al più p + 1 segmenti). La regione grigia piena è l'inviluppo convesso dei p + 1 punti attivi dell'intervallo che contiene u: tutto quel pezzo di curva vi giace dentro (inviluppo convesso forte), una regione molto più stretta dell'inviluppo dell'intero poligono (contornato).",
  "localControl.try1":
    "Trascina P₄ e osserva le estremità della curva: per u in [0, 1] e [5, 6] nulla si muove, esattamente dove la banda si ferma.",
  "localControl.try2":
    "Digita 5/2 per u: l'intervallo è k = 5, i punti attivi sono P₂ … P₅ con pesi 1/48, 23/48, 23/48, 1/48, e C(u) sta dentro il loro inviluppo ombreggiato.",
  "localControl.try3":
    "Imposta il grado a 1 e poi a 5: la banda e l'inviluppo attivo crescono con p (p + 1 intervalli, p + 1 punti), e con grado 1 la curva è il poligono stesso.",
  "knotInsertion.title": "Inserimento di nodi (Boehm) ed estrazione di Bézier",
  "knotInsertion.summary":
    "Inserisci un nodo e la curva mantiene la sua forma mentre il poligono di controllo guadagna un punto e si avvicina; inseriscine abbastanza e la curva si scompone in segmenti di Bézier.",
  "knotInsertion.control.u": "Nodo da inserire, u",
  "knotInsertion.control.u.input": "valore di u (decimale o frazione come 3/2)",
  "knotInsertion.control.insert": "Inserisci",
  "knotInsertion.control.insert.title": "Inserisci il nodo u una volta (o fai clic sulla curva)",
  "knotInsertion.control.refine": "Dimezza ogni intervallo",
  "knotInsertion.control.refine.title": "Inserisci il punto medio di ogni intervallo non vuoto",
  "knotInsertion.control.reset": "Torna all'originale",
  "knotInsertion.control.reset.title":
    "Rimuovi ogni nodo inserito (i punti originali restano come sono)",
  "knotInsertion.control.bezier": "Estrai i segmenti di Bézier",
  "knotInsertion.error.tooFewPoints":
    "campo “points”: il grado {p} richiede almeno {min} punti di controllo, ricevuti {count}",
  "knotInsertion.error.knotOrder":
    "il campo “knots” non deve decrescere (il nodo {i} è minore del precedente)",
  "knotInsertion.error.emptyDomain": "campo “knots”: il dominio [u_p, u_n+1] è vuoto",
  "knotInsertion.error.insertedRange": "campo “inserted”: {value} è fuori dal dominio [{a}; {b}]",
  "knotInsertion.outside": "u = {value} è fuori dal dominio [{a}; {b}]",
  "knotInsertion.refused": "impossibile inserire quel nodo: {message}",
  "knotInsertion.maxInserted":
    "questa demo inserisce al massimo {max} nodi; premi “Torna all'originale” per ricominciare",
  "knotInsertion.hoverLabel": "inserisci u = {u}",
  "knotInsertion.formula.preview": "L'inserimento userebbe:",
  "knotInsertion.readout": "{count} punti di controllo, {knots} nodi",
  "knotInsertion.segments.many": "{count} segmenti di Bézier (uno per intervallo non vuoto)",
  "knotInsertion.segments.one": "{count} segmento di Bézier (uno per intervallo non vuoto)",
  "knotInsertion.segments.other": "{count} segmenti di Bézier (uno per intervallo non vuoto)",
  "knotInsertion.segmentsOff":
    "Spunta la casella per disegnare il poligono di ogni segmento di Bézier.",
  "knotInsertion.knotsNow": "Nodi: {knots}",
  "knotInsertion.knotsNone": "Nessun nodo ancora inserito: fai clic sulla curva o premi Inserisci.",
  "knotInsertion.knotsBefore": "Nodi prima di inserire {s}: {knots}",
  "knotInsertion.knotsAfter": "Nodi dopo: {knots}",
  "knotInsertion.alphasPreview": "Inserire {s} userebbe {alphas}",
  "knotInsertion.alphasUsed": "α usati: {alphas}",
  "knotInsertion.insertedList": "Nodi inseriti ({count}), in ordine: {knots}",
  "knotInsertion.insertedNone": "Nodi inseriti: nessuno",
  "knotInsertion.tableCaption":
    "I nuovi punti di controllo dopo aver inserito {s}: quelli evidenziati sono nuovi, gli altri sono copiati",
  "knotInsertion.tableEmpty": "I nuovi punti di controllo compaiono qui dopo un inserimento.",
  "knotInsertion.aria":
    "B-spline {kind} con {count} punti di controllo e {knots} nodi dopo aver inserito u = {s} con α = {alphas}; la curva non cambia{segments}",
  "knotInsertion.ariaNone":
    "B-spline {kind} con {count} punti di controllo e {knots} nodi; inserire u = {s} userebbe α = {alphas}{segments}",
  "knotInsertion.ariaSegments.many": "; {count} segmenti di Bézier mostrati",
  "knotInsertion.ariaSegments.one": "; {count} segmento di Bézier mostrato",
  "knotInsertion.ariaSegments.other": "; {count} segmenti di Bézier mostrati",
  "knotInsertion.whatYouSee":
    "La B-spline quadratica dell'esempio delle dispense croate (p = 2, nodi 0 0 0 1 2 3 4 4 4; sezione 3 del programma), dopo l'inserimento del nodo 1,5. Inserire un nodo s con la regola di Boehm mantiene i primi punti, ne sostituisce p con punti Qᵢ sui lati del vecchio poligono (nel rapporto αᵢ) e sposta i restanti: la curva (blu) non cambia affatto, ma il nuovo poligono (scuro, nuovi punti in vermiglio) ha un punto in più e le sta più vicino; il vecchio poligono resta in trasparenza. Inserire ogni nodo interno fino a molteplicità p dà i segmenti di Bézier della curva, uno per intervallo non vuoto.",
  "knotInsertion.try1":
    "La figura si apre dopo l'inserimento di u = 1,5: i nodi sono diventati 0; 0; 0; 1; 1,5; 2; 3; 4; 4; 4 e α₂ = 3/4, α₃ = 1/4 tagliano i lati P₁P₂ e P₂P₃. Premi “Torna all'originale”, poi Inserisci con u = 1,5 per vederlo accadere.",
  "knotInsertion.try2":
    "Fai clic sulla curva in più punti, o premi “Dimezza ogni intervallo” tre volte: il poligono si stringe sulla curva.",
  "knotInsertion.try3":
    "Spunta “Estrai i segmenti di Bézier”: 5 segmenti, uno per intervallo non vuoto ([0; 1], [1; 1,5], [1,5; 2], [2; 3], [3; 4]); inserisci di nuovo 1,5 e non si aggiunge nulla, perché quell'intervallo c'è già.",
  "multiplicity.title": "Molteplicità e continuità",
  "multiplicity.summary":
    "Fondi i nodi di una B-spline cubica e osserva la continuità scendere C², C¹, C⁰ (uno spigolo in un punto di controllo), poi una rottura; ripeti un punto di controllo e la curva viene attratta in esso.",
  "multiplicity.aria":
    "B-spline cubica con {count} punti di controllo e nodi [{knots}]; nei nodi interni (molteplicità: garantita, misurata): {list}{through}{repeat}",
  "multiplicity.ariaThrough": "; la curva passa per {point} in u = {u}",
  "multiplicity.ariaRepeat":
    "; punto di controllo ripetuto: {points}, continuità misurata {measured}",
  "multiplicity.knotLegend": "Molteplicità del nodo",
  "multiplicity.knotReadout":
    "{names} = {u} · r = {r} · garantita {guaranteed} · misurata {measured}",
  "multiplicity.noKnot": "Nessun nodo interno",
  "multiplicity.knotHint":
    "Seleziona un nodo sul righello (fai clic, o Tab oltre l'ultimo punto di controllo) per studiarlo; fai doppio clic o premi Invio per fondere su di esso il nodo successivo.",
  "multiplicity.through":
    "Con r = 3 la curva passa per un punto di controllo: C({u}) = {point}, con uno spigolo.",
  "multiplicity.throughLabel": "C({u}) = {point}",
  "multiplicity.pointLabel": "C({u})",
  "multiplicity.jointLabel": "u = {u}",
  "multiplicity.raise": "Aumenta r (Invio)",
  "multiplicity.raise.title": "Fondi il nodo successivo sul nodo studiato",
  "multiplicity.lower": "Diminuisci r (Canc)",
  "multiplicity.lower.title":
    "Sposta la copia superiore del nodo studiato a metà strada verso il nodo successivo",
  "multiplicity.resetKnots": "Nodi uniformi vincolati",
  "multiplicity.resetKnots.title":
    "Sostituisci i nodi con 4 nodi uguali agli estremi e nodi interni equidistanti",
  "multiplicity.multiplicity.max": "il nodo ha già la molteplicità massima, p + 1 = {max}",
  "multiplicity.multiplicity.ends": "non resta alcun nodo interno da fondere su questo",
  "multiplicity.multiplicity.single": "questo è un nodo semplice: niente da separare",
  "multiplicity.repeatLegend": "Molteplicità del punto di controllo",
  "multiplicity.repeatOption": "×{k}",
  "multiplicity.repeatNone":
    "{point} compare una volta. Seleziona un punto di controllo e scegli ×2 o ×3 per ripeterlo.",
  "multiplicity.repeatReadout": "{points}: in u{k} = {u} misurata {measured}",
  "multiplicity.repeatEnd": "{points}: troppo vicino a un estremo della curva per un nodo interno",
  "multiplicity.repeatHint":
    "Ripetere un punto aggiunge punti di controllo, quindi i nodi tornano uniformi vincolati.",
  "multiplicity.notesCaption":
    "La tabella delle dispense croate per le cubiche (i casi attuali evidenziati)",
  "multiplicity.notesBreak": "rottura (pezzi separati)",
  "multiplicity.colMultiplicity": "Molteplicità",
  "multiplicity.colPoints": "Punti di controllo",
  "multiplicity.colKnots": "Nodi",
  "multiplicity.knotsCaption":
    "Ogni nodo interno: la C^(p − r) garantita dal vettore dei nodi, e ciò che il nucleo di calcolo misura nella giunzione dei pezzi di Bézier",
  "multiplicity.colKnot": "Nodo",
  "multiplicity.colR": "r",
  "multiplicity.colGuaranteed": "Garantita",
  "multiplicity.colMeasured": "Misurata",
  "multiplicity.colPoint": "C(u)",
  "multiplicity.colThrough": "Passa per",
  "multiplicity.pointBreak": "il pezzo sinistro finisce in {left}, il destro inizia in {right}",
  "multiplicity.formulaRule": "in un nodo di molteplicità",
  "multiplicity.formulaBreak": "rottura",
  "multiplicity.formulaMeasured": "misurata:",
  "multiplicity.whatYouSee":
    "Una B-spline cubica (blu) su otto punti di controllo e, sotto, il suo righello dei nodi: 0 0 0 0 1 2 3 4 5 5 5 5. Fondere i nodi aumenta la molteplicità r di un nodo e lì la continuità scende a C^(3 − r): con r = 2 la curva è C¹, con r = 3 solo C⁰ — passa per un punto di controllo e forma uno spigolo — e con r = 4 si spezza in due pezzi di Bézier separati. Ripetere invece un punto di controllo mantiene la C² parametrica, ma un punto triplo ferma la curva (velocità nulla) e dà uno spigolo, G⁰. La tabella è quella delle dispense croate (sezione 3 del programma); “misurata” è ciò che il nucleo di calcolo trova confrontando le derivate dei pezzi di Bézier in ogni giunzione. Per un punto doppio le dispense scrivono G¹; la misura dà G², perché la curvatura resta continua (scende a zero nei due nodi accanto al punto).",
  "multiplicity.try1":
    "Fai clic su u₅ (il nodo in 2) sul righello e premi Invio tre volte: l'indicazione passa a C¹, C⁰ — ora la curva passa per P₄ con uno spigolo — e poi a “rottura”.",
  "multiplicity.try2":
    "Seleziona P₄ e scegli ×3: la curva viene attratta nel punto e lì gira con uno spigolo, misurata C² G⁰; con ×2 si avvicina soltanto.",
  "multiplicity.try3":
    "Trascina un nodo sul righello sopra il suo vicino: la continuità scritta sopra scende appena i due si incontrano.",
  "matrixForm.title": "Forma matriciale dei segmenti uniformi",
  "matrixForm.summary":
    "Ogni segmento di una B-spline uniforme è [tᵖ … t 1] · M · (i suoi p + 1 punti), con la stessa matrice M per ogni segmento interno.",
  "matrixForm.aria":
    "B-spline {kind}, {knots}, {count} punti di controllo; segmento {i} in t = {t}: punto ({x}; {y}); {periodic}",
  "matrixForm.aria.periodic": "la sua matrice è quella periodica",
  "matrixForm.aria.notPeriodic": "la sua matrice differisce da quella periodica",
  "matrixForm.degree.2": "quadratica (p = 2)",
  "matrixForm.degree.3": "cubica (p = 3)",
  "matrixForm.knots.uniform": "nodi uniformi (non vincolati)",
  "matrixForm.knots.clamped": "nodi vincolati",
  "matrixForm.control.degree": "Grado",
  "matrixForm.control.knots": "Vettore dei nodi",
  "matrixForm.control.segment": "Segmento i (o fai clic sulla curva)",
  "matrixForm.control.segment.input": "numero del segmento i",
  "matrixForm.control.t": "Parametro locale t",
  "matrixForm.segmentRange":
    "il segmento deve essere un numero intero da 1 a {max}, ricevuto “{value}”",
  "matrixForm.periodic.yes": "Segmento {i}: matrice periodica",
  "matrixForm.periodic.no": "Segmento {i}: matrice propria",
  "matrixForm.degree": "Grado p = {p}, {count} punti di controllo, {segments}; nodi {knots}",
  "matrixForm.segments.many": "{count} segmenti",
  "matrixForm.segments.one": "{count} segmento",
  "matrixForm.segments.other": "{count} segmenti",
  "matrixForm.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "matrixForm.minPoints": "qui il grado {p} richiede almeno {min} punti di controllo",
  "matrixForm.error.degree":
    "il campo “degree” vale {p}, ma {count} punti di controllo consentono al massimo il grado {count} − 1",
  "matrixForm.matrixCaption":
    "M del segmento {i} (intervallo k = {k}), da segmentMatrix(k): riga = potenza di t, colonna = il punto che moltiplica",
  "matrixForm.resultCaption":
    "Il punto in t, due volte: il prodotto dei numeri sopra, e evaluate(u) del nucleo di calcolo",
  "matrixForm.result.product": "[tᵖ … 1] · M · punti",
  "matrixForm.result.evaluate": "evaluate(u)",
  "matrixForm.pointLabel": "C{i}(t)",
  "matrixForm.tex.periodic": "(segmento periodico: uniformSegmentMatrix(p))",
  "matrixForm.tex.notPeriodic": "uniformSegmentMatrix(p): un segmento estremo di nodi vincolati",
  "matrixForm.tex.evaluate": "nucleo:",
  "matrixForm.whatYouSee":
    "Su un intervallo una B-spline è un polinomio nel parametro locale t, quindi ogni segmento si può scrivere come una riga di potenze di t, per una matrice M, per i p + 1 punti che agiscono lì — la forma matriciale delle dispense croate (sezione 3 del programma). Con nodi uniformi ogni segmento ha la stessa M (le dispense li chiamano segmenti periodici): [[1/2, −1, 1/2], [−1, 1, 0], [1/2, 1/2, 0]] per le quadratiche, 1/6·[[−1, 3, −3, 1], [3, −6, 3, 0], [−3, 0, 3, 0], [1, 4, 1, 0]] per le cubiche. Con nodi vincolati i segmenti estremi hanno matrici proprie.",
  "matrixForm.try1":
    "Muovi il cursore del segmento: il tratto evidenziato e i suoi punti colorati si spostano, ma M resta la stessa.",
  "matrixForm.try2":
    "Passa ai nodi vincolati e scegli il segmento 1: M cambia (la curva deve partire da P₀); con 6 punti e p = 2 i segmenti 2 e 3 mantengono la matrice periodica, come nell'esempio delle dispense.",
  "matrixForm.try3":
    "Trascina uno dei punti cerchiati e confronta le due righe della tabella dei risultati: il prodotto matriciale e evaluate(u) coincidono in ogni cifra decimale.",
  "weights.title": "Pesi di una curva razionale",
  "weights.summary":
    "Aumenta un peso e la curva viene attratta verso il suo punto di controllo; la figura omogenea mostra perché: una curva polinomiale in (wx, wy, w) proiettata su w = 1.",
  "weights.whatYouSee":
    "Una curva di Bézier razionale cubica (blu) e gli stessi punti di controllo con tutti i pesi pari a 1 (punteggiata): l'anello attorno a ogni punto cresce con il suo peso wᵢ, e aumentare wᵢ attrae la curva verso Pᵢ. Il riquadro mostra la figura omogenea delle dispense greche (sezione 4 del programma): i punti (wᵢxᵢ, wᵢyᵢ, wᵢ) generano una normale curva di Bézier polinomiale nello spazio (verde), e i raggi dall'origine la proiettano sul piano w = 1, dove è la curva razionale. Moltiplicare ogni peso per lo stesso numero sposta la curva verde lungo i raggi ma non la sua proiezione: contano solo i rapporti tra i pesi.",
  "weights.try1":
    "Trascina il cursore di w₁ (o l'anello attorno a P₁) da 0,1 a 10 e osserva P(1/2) scivolare verso P₁; l'ultima colonna della tabella mostra la distanza che diminuisce.",
  "weights.try2": "Premi “Tutti i pesi × 2”: la curva verde nel riquadro si sposta, quella blu no.",
  "weights.try3":
    "Premi “Tutti i pesi 1”: la curva razionale ricade sulla curva polinomiale punteggiata.",
  "weights.handleLabel": "P{i} (w{i} = {w})",
  "weights.countMismatch":
    "il campo “weights” deve avere un peso per punto: {count} pesi per {points} punti",
  "weights.notPositive": "campo “weights”: {name} = {value} rifiutato; i pesi devono essere > 0",
  "weights.outOfRange": "campo “weights”: {name} deve essere tra {min} e {max}, ricevuto {value}",
  "weights.weightsLegend": "Pesi (scala logaritmica)",
  "weights.weightLabel": "Peso {name} di {point}",
  "weights.weightInput": "Peso {name} (un numero tra 0,1 e 10)",
  "weights.badWeight":
    "peso {name} = “{value}” rifiutato: un peso deve essere > 0 (qui tra {min} e {max})",
  "weights.allOne": "Tutti i pesi 1",
  "weights.allOne.title": "Imposta ogni peso a 1: la curva di Bézier polinomiale",
  "weights.scaleAll": "Tutti i pesi × {factor}",
  "weights.scaleAll.title": "Moltiplica ogni peso per lo stesso numero: la curva non cambia",
  "weights.cannotScale":
    "i pesi non possono essere tutti raddoppiati o dimezzati entro {min} … {max}",
  "weights.scaled":
    "Ogni peso {factor}: la curva blu resta dov'era (contano solo i rapporti); la curva omogenea nel riquadro si è spostata lungo i raggi.",
  "weights.showHomogeneous": "Mostra lo spazio omogeneo (riquadro)",
  "weights.maxPoints": "questa demo consente al massimo {max} punti di controllo",
  "weights.minPoints": "questa demo richiede almeno {min} punti di controllo",
  "weights.degree": "Grado n = {n} ({count} punti di controllo)",
  "weights.pointLabel": "P({t})",
  "weights.ghostPointLabel": "t = {t}, tutti i wᵢ = 1",
  "weights.legendRational": "curva razionale",
  "weights.legendPolynomial": "tutti i pesi 1",
  "weights.insetTitle": "Spazio omogeneo (wx, wy, w)",
  "weights.axisX": "wx",
  "weights.axisY": "wy",
  "weights.axisW": "w",
  "weights.origin": "O",
  "weights.plane": "w = 1",
  "weights.readout": "P({t}) = ({x}; {y}); distanza massima dalla curva polinomiale: {gap}",
  "weights.tableCaption":
    "Punti di controllo, pesi, punti omogenei (wᵢxᵢ, wᵢyᵢ, wᵢ), la quota Bᵢ(t)wᵢ / Σ Bⱼ(t)wⱼ di ogni punto in t = {t}, e la distanza |P(t) − Pᵢ|",
  "weights.column.point": "Pᵢ",
  "weights.column.weight": "wᵢ",
  "weights.column.homogeneous": "Pᵢʷ = (wᵢxᵢ, wᵢyᵢ, wᵢ)",
  "weights.column.share": "quota in t",
  "weights.column.distance": "|P(t) − Pᵢ|",
  "weights.tex.ratios": "contano solo i rapporti: ",
  "weights.tex.same": " dà la stessa curva",
  "weights.aria":
    "Curva di Bézier razionale {kind} con pesi ({weights}) e, punteggiata, la curva polinomiale con tutti i pesi 1; in t = {t} il punto P(t) = ({x}; {y}) (tutti i pesi 1: ({gx}; {gy})), a {distance} dal punto più pesante {heaviest}; riquadro: i punti di controllo omogenei, la loro curva polinomiale in (wx, wy, w) e i raggi dall'origine che la proiettano sul piano w = 1",
  "conics.title": "Sezioni coniche",
  "conics.summary":
    "Una curva di Bézier razionale quadratica è una conica: un arco di ellisse per w₁ < 1, una parabola per w₁ = 1, un'iperbole sopra; con un triangolo isoscele e w₁ = sin θ, un arco di circonferenza.",
  "conics.whatYouSee":
    "Una curva di Bézier razionale quadratica (blu) con pesi 1, w₁, 1 e, punteggiata, la parabola che essa è per w₁ = 1. Il nucleo di calcolo riconosce la conica dal fattore di forma k = w₁²/(w₀w₂): sotto 1 un arco di ellisse, uguale a 1 una parabola, sopra 1 un'iperbole; il punto di spalla P(1/2) scorre lungo la retta dal punto medio M della corda a P₁. Quando il triangolo è isoscele e w₁ = sin θ, con θ metà dell'angolo in P₁, l'arco è esattamente circolare: appare l'intera circonferenza, tratteggiata, con il suo centro. È la parte sulle coniche delle dispense greche (sezione 4 del programma).",
  "conics.try1":
    "Digita 0,5, poi 1 e 2 nella casella di w₁: il nome passa da ellisse a parabola a iperbole, e la riga della tabella segue.",
  "conics.try2":
    "Premi “Rendi circolare”: w₁ diventa sin θ e appare la circonferenza tratteggiata; poi trascina P₂ e osserva “circonferenza!” sparire.",
  "conics.try3":
    "Porta w₁ fino a 5: il punto di spalla corre verso P₁ e l'iperbole aderisce al triangolo di controllo.",
  "conics.w1": "Peso centrale w₁ (scala logaritmica)",
  "conics.w1.input": "Peso w₁ (un numero tra 0,05 e 5)",
  "conics.badWeight": "peso w₁ = “{value}” rifiutato: w₁ deve essere > 0 (qui tra {min} e {max})",
  "conics.makeCircular": "Rendi circolare",
  "conics.makeCircular.title":
    "Rendi isoscele il triangolo (P₂ scorre lungo P₁P₂) e imposta w₁ = sin θ, il peso di un arco di circonferenza",
  "conics.circleLegend": "Arco di circonferenza",
  "conics.notCircular": "nessun arco di circonferenza per questo triangolo: {message}",
  "conics.tooFlat":
    "l'arco di circonferenza richiede w₁ = {w}, sotto il peso minimo di questa demo {min}",
  "conics.madeCircular": "w₁ = sin θ = {w}: un arco di circonferenza.",
  "conics.kind.ellipse": "ellisse",
  "conics.kind.parabola": "parabola",
  "conics.kind.hyperbola": "iperbole",
  "conics.article.ellipse": "un'ellisse",
  "conics.article.parabola": "una parabola",
  "conics.article.hyperbola": "un'iperbole",
  "conics.rule.ellipse": "k = w₁²/(w₀w₂) < 1",
  "conics.rule.parabola": "k = 1 (w₁ = 1: la curva di Bézier polinomiale)",
  "conics.rule.hyperbola": "k > 1",
  "conics.column.kind": "conica",
  "conics.column.rule": "regola (w₀ = w₂ = 1)",
  "conics.tableCaption":
    "Quale conica: decide il fattore di forma k (quella attuale è evidenziata)",
  "conics.figureCircle": "{kind}: circonferenza!",
  "conics.readoutCircle": "{kind}: circonferenza!",
  "conics.centre": "O",
  "conics.midpoint": "M",
  "conics.shoulder": "P(1/2)",
  "conics.legendParabola": "w₁ = 1 (parabola)",
  "conics.formula.circularArc": "arco di circonferenza",
  "conics.formula.and": "e",
  "conics.formula.circle": "circonferenza!",
  "conics.shape": "w₁ = {w}; fattore di forma k = w₁²/(w₀w₂) = {k} {relation} 1",
  "conics.triangle":
    "|P₀P₁| = {a}, |P₁P₂| = {b} (non isoscele); angolo in P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleIsosceles":
    "|P₀P₁| = |P₁P₂| = {a} (isoscele); angolo in P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleDegenerate": "Due punti coincidono: nessun angolo in P₁.",
  "conics.circleYes":
    "circonferenza! raggio {r}; la distanza di ogni campione dal centro O differisce da esso al più di {error}.",
  "conics.circleNo":
    "Non ancora circolare: l'arco richiede w₁ = sin θ = {sin} (distanza massima da quella circonferenza ora: {error}).",
  "conics.circleNeedsIsosceles":
    "Non circolare: un arco di circonferenza richiede |P₀P₁| = |P₁P₂| (premi “Rendi circolare”).",
  "conics.aria":
    "Curva di Bézier razionale quadratica con P₀ = {p0}, P₁ = {p1}, P₂ = {p2} e pesi 1; {w}; 1: un arco di {kind} (fattore di forma {k}){circle}; punto di spalla P(1/2) = ({sx}; {sy}); punteggiata: la parabola con w₁ = 1",
  "conics.ariaCircle": ", un arco di circonferenza di raggio {r} attorno a ({x}; {y})",
  "nurbsCircle.title": "Circonferenze e archi NURBS",
  "nurbsCircle.summary":
    "Una circonferenza esatta come NURBS di grado 2: 9 punti di controllo, pesi 1 e √2/2, nodi 0; 0; 0; ¼; ¼; ½; ½; ¾; ¾; 1; 1; 1. Archi in pezzi di al più 90°, ellissi come loro immagini affini.",
  "nurbsCircle.whatYouSee":
    "Una circonferenza (o un arco, o un'ellisse) costruita dal nucleo di calcolo come NURBS di grado 2 (blu), il suo poligono di controllo con il peso di ogni punto, e le giunzioni dei suoi pezzi (anelli verdi). La circonferenza completa è la NURBS a 9 punti del programma (sezione 4, dalle dispense greche e italiane): gli angoli del quadrato hanno peso √2/2, i nodi sono 0; 0; 0; ¼; ¼; ½; ½; ¾; ¾; 1; 1; 1. Un arco è diviso in pezzi di al più 90° i cui pesi centrali sono cos(Δ/2). L'indicatore misura quanto 2000 campioni distano dalla circonferenza esatta: 0 o qualche 10⁻¹⁶, solo arrotondamento — nessuna curva polinomiale può farlo.",
  "nurbsCircle.try1":
    "Imposta l'ampiezza a 200°: l'arco ha 3 pezzi di 66,7° e pesi centrali cos 33,3° ≈ 0,835; l'errore sul raggio indica ancora circa 1e-16.",
  "nurbsCircle.try2":
    "Spunta “Ellisse” e ruota: stessi pesi e nodi, punti di controllo stirati — un'immagine affine della circonferenza.",
  "nurbsCircle.try3": "Trascina il centro c: l'intera circonferenza si sposta e resta esatta.",
  "nurbsCircle.notPositive": "il campo “{field}” deve essere > 0, ricevuto {value}",
  "nurbsCircle.zeroSweep":
    "il campo “sweep” non deve essere 0 (un arco richiede un'ampiezza non nulla)",
  "nurbsCircle.radius": "Raggio r",
  "nurbsCircle.radius.input": "Raggio (un numero > 0, fino a 10)",
  "nurbsCircle.rx": "Semiasse rx",
  "nurbsCircle.rx.input": "Semiasse rx (un numero > 0, fino a 10)",
  "nurbsCircle.ry": "Semiasse ry",
  "nurbsCircle.ry.input": "Semiasse ry (un numero > 0, fino a 10)",
  "nurbsCircle.rotation": "Rotazione (gradi)",
  "nurbsCircle.rotation.input": "Rotazione dell'ellisse in gradi",
  "nurbsCircle.start": "Angolo iniziale (gradi)",
  "nurbsCircle.start.input": "Angolo iniziale in gradi",
  "nurbsCircle.sweep": "Ampiezza (gradi, negativa: senso orario)",
  "nurbsCircle.sweep.input": "Ampiezza in gradi, da −360 a 360, non 0",
  "nurbsCircle.badLength":
    "{field} = “{value}” rifiutato: {field} deve essere > 0 (qui tra {min} e {max})",
  "nurbsCircle.badAngle": "{field} = “{value}” rifiutato: serve un angolo tra −{max}° e {max}°",
  "nurbsCircle.ellipseMode": "Ellisse (semiassi e rotazione)",
  "nurbsCircle.circleLegend": "Circonferenza",
  "nurbsCircle.ellipseLegend": "Ellisse",
  "nurbsCircle.arcLegend": "Arco",
  "nurbsCircle.resultLegend": "La NURBS",
  "nurbsCircle.full": "Giro completo",
  "nurbsCircle.full.title": "Inizio 0°, ampiezza 360°: la curva chiusa a 9 punti",
  "nurbsCircle.refused": "rifiutato dalla libreria: {message}",
  "nurbsCircle.centreLabel": "c",
  "nurbsCircle.radiusLabel": "r = {r}",
  "nurbsCircle.axesLabel": "rx = {rx}; ry = {ry}",
  "nurbsCircle.errorCircle": "errore sul raggio {error}",
  "nurbsCircle.errorEllipse": "errore sull'ellisse {error}",
  "nurbsCircle.errorCircleNote":
    "max | |C(u) − c| − r | su {samples} campioni (solo arrotondamento: la curva è esatta)",
  "nurbsCircle.errorEllipseNote":
    "max | (x′/rx)² + (y′/ry)² − 1 | su {samples} campioni, x′, y′ lungo gli assi",
  "nurbsCircle.count": "{count} punti di controllo, {pieces} pezzi (≤ 90° ciascuno)",
  "nurbsCircle.knots": "Nodi: {knots}",
  "nurbsCircle.ariaCircle": "circonferenza di raggio {r}",
  "nurbsCircle.ariaEllipse": "ellisse con semiassi {rx} e {ry} ruotata di {rotation}°",
  "nurbsCircle.ariaFull": "la curva intera",
  "nurbsCircle.ariaArc": "un arco da {start}° di ampiezza {sweep}°",
  "nurbsCircle.aria":
    "NURBS, {shape}, centrata in ({x}; {y}), {arc}: grado 2, {count} punti di controllo con pesi {weights}, nodi {knots}, {pieces} pezzi; errore misurato {error}",
  "nurbsCircle.tableCaption": "I {count} punti di controllo e i loro pesi",
  "nurbsCircle.column.point": "Pᵢ",
  "nurbsCircle.column.weight": "wᵢ",
  "nurbsCircle.formula.circle": "circonferenza",
  "nurbsCircle.formula.here": "qui",
  "nurbsCircle.formula.pieces.many": "pezzi di",
  "nurbsCircle.formula.pieces.one": "pezzo di",
  "nurbsCircle.formula.pieces.other": "pezzi di",
  "nurbsCircle.formula.middleWeights": "pesi centrali",
  "nurbsCircle.formula.samples": "campioni",
  "projective.title": "Invarianza proiettiva",
  "projective.summary":
    "Trasforma una curva razionale con una prospettiva: trasformare i suoi punti di controllo e pesi dà esattamente la curva trasformata; trasformare i punti e tenere i vecchi pesi no.",
  "projective.whatYouSee":
    "A sinistra una curva di Bézier cubica nel quadrato S₀S₁S₂S₃; a destra la sua immagine tramite la trasformazione prospettica H che manda il quadrato nel quadrilatero Q₀Q₁Q₂Q₃ (trascina gli angoli). Il nucleo di calcolo trasforma con H i punti di controllo omogenei della curva (wᵢPᵢ, wᵢ), ottenendo nuovi punti e nuovi pesi (blu continua); i punti arancioni sono i campioni della curva originale trasformati uno per uno con la stessa H, e giacciono esattamente su di essa — le curve razionali sono invarianti per trasformazioni proiettive, come dicono le dispense greche (sezione 4 del programma). La curva tratteggiata usa i punti trasformati con i vecchi pesi: sbaglia, perché una prospettiva cambia i pesi.",
  "projective.try1":
    "Trascina Q₂ verso Q₃: la prospettiva si accentua, i pesi trasformati si allontanano tra loro, e la curva tratteggiata si scosta sempre più dai punti, che restano sulla curva continua.",
  "projective.try2":
    "Premi “Rendi affine”: il quadrilatero diventa un parallelogramma, ogni peso trasformato è quello vecchio, e la curva tratteggiata si unisce alle altre.",
  "projective.try3":
    "Trascina Q₂ oltre la diagonale Q₁Q₃: la trasformazione porterebbe un punto di controllo oltre la retta all'infinito (un peso ≤ 0); la libreria rifiuta e resta l'ultima figura valida.",
  "projective.notPositive": "campo “weights”: {name} = {value} rifiutato; i pesi devono essere > 0",
  "projective.weightRange":
    "campo “weights”: {name} deve essere tra {min} e {max}, ricevuto {value}",
  "projective.degenerate":
    "campo “corners”: i quattro angoli non definiscono una trasformazione prospettica (tre di essi allineati?)",
  "projective.weightsLegend": "Pesi originali (scala logaritmica)",
  "projective.weightLabel": "Peso {name} di {point}",
  "projective.weightInput": "Peso {name} (un numero tra 0,1 e 10)",
  "projective.badWeight":
    "peso {name} = “{value}” rifiutato: un peso deve essere > 0 (qui tra {min} e {max})",
  "projective.affine": "Rendi affine",
  "projective.affine.title":
    "Sposta Q₂ in modo che il quadrilatero sia un parallelogramma: una trasformazione affine, pesi invariati",
  "projective.resultLegend": "Verifica dell'invarianza",
  "projective.refused": "la libreria ha rifiutato questa trasformazione: {message}",
  "projective.mappedLabel": "w′{i} = {w}",
  "projective.naiveLabel": "non invariante: pesi ignorati",
  "projective.legendMapped": "curve.projectiveMap(H)",
  "projective.legendPointwise": "H applicata a ogni campione",
  "projective.legendNaive": "punti trasformati, vecchi pesi",
  "projective.gaps":
    "Continua e punti: scarto massimo {ab} (la stessa curva). Tratteggiata e continua: {ac}.",
  "projective.mappedWeights": "Pesi trasformati w′ᵢ: {weights}",
  "projective.affineMap": "una trasformazione affine",
  "projective.perspectiveMap": "una trasformazione prospettica",
  "projective.tex.affine": "(trasformazione affine: ",
  "projective.tex.unchanged": ", pesi invariati)",
  "projective.tex.invariant": "(invariante)",
  "projective.tex.ignored": "(pesi ignorati)",
  "projective.aria":
    "Una curva di Bézier cubica nel quadrato [0, 4]² e la sua immagine tramite {kind} che manda gli angoli del quadrato in {corners}: la curva trasformata ha pesi {weights}; i campioni originali trasformati uno per uno giacciono su di essa (scarto massimo {ab}); i punti trasformati con i vecchi pesi danno una curva diversa (distante fino a {ac})",
  "negativeWeights.title": "Perché i pesi non positivi sono rifiutati",
  "negativeWeights.summary":
    "Porta un peso oltre lo zero: la libreria rifiuta, e la demo mostra cosa farebbe la curva — uscire dal suo inviluppo convesso e fuggire all'infinito dove il denominatore w(t) si annulla.",
  "negativeWeights.whatYouSee":
    "Una curva di Bézier razionale quadratica con pesi 1, w₁, 1 sul suo triangolo di controllo (l'inviluppo convesso, ombreggiato). Finché w₁ > 0 la libreria costruisce la curva (blu) e questa resta nel triangolo. Con w₁ ≤ 0 la libreria rifiuta, e il suo messaggio è mostrato parola per parola; la curva tratteggiata è ciò che darebbe la formula: la curva omogenea (wx, wy, w) è ancora una normale curva polinomiale, e dividere per w la proietta indietro. Sotto, il denominatore w(t) = Σ Bᵢ(t)wᵢ: dove attraversa lo zero il punto fugge all'infinito (un polo), e qualunque peso negativo spinge già la curva fuori dal suo inviluppo convesso. È l'avvertimento delle dispense greche (sezione 4 del programma): i pesi negativi rompono la proprietà dell'inviluppo convesso e possono creare poli.",
  "negativeWeights.try1":
    "Premi “w₁ = −0,5”: la libreria rifiuta, la curva si rovescia sotto la corda P₀P₂ ed esce dal triangolo, ma w(t) resta sopra 0 — ancora nessun polo.",
  "negativeWeights.try2":
    "Trascina lentamente w₁ da 0 fino a −3: con w₁ = −1 il grafico tocca lo zero in t = 1/2, sotto lo attraversa due volte e la curva si spezza in corrispondenza di due poli.",
  "negativeWeights.try3": "Premi “w₁ = 1”: il messaggio scompare e torna la normale parabola.",
  "negativeWeights.w1": "Peso centrale w₁ (qui può essere ≤ 0)",
  "negativeWeights.w1.input": "Peso w₁ (un numero tra −3 e 3)",
  "negativeWeights.badWeight":
    "peso w₁ = “{value}” rifiutato: questa demo accetta w₁ tra {min} e {max}",
  "negativeWeights.preset": "w₁ = {w}",
  "negativeWeights.libraryLegend": "Cosa dice la libreria",
  "negativeWeights.resultLegend": "Cosa darebbe la formula",
  "negativeWeights.refused": "la libreria rifiuta i pesi 1, w₁, 1: {message}",
  "negativeWeights.accepted": "La libreria accetta questi pesi.",
  "negativeWeights.libraryRefuses":
    "new BezierCurve(points, 2, weights) solleva un errore: “{message}”",
  "negativeWeights.libraryAccepts":
    "new BezierCurve(points, 2, weights) accetta questi pesi: ogni wᵢ > 0.",
  "negativeWeights.poles.many": "{count} poli, in t ≈ {list}",
  "negativeWeights.poles.one": "1 polo, in t ≈ {list}",
  "negativeWeights.poles.other": "{count} poli, in t ≈ {list}",
  "negativeWeights.noPoles": "nessun polo: w(t) > 0 su [0, 1]",
  "negativeWeights.outside":
    "La curva esce dal suo inviluppo convesso (il triangolo di controllo).",
  "negativeWeights.inside":
    "La curva resta nel suo inviluppo convesso (il triangolo di controllo).",
  "negativeWeights.poleLabel": "polo t ≈ {t}",
  "negativeWeights.infinity": "∞",
  "negativeWeights.middleLabel": "P(1/2)",
  "negativeWeights.figureAccepted": "pesi > 0: la curva della libreria",
  "negativeWeights.figureRefused": "rifiutata dalla libreria (tratteggiata: la formula)",
  "negativeWeights.tickHalf": "1/2",
  "negativeWeights.axisT": "t",
  "negativeWeights.plotTitle": "denominatore w(t) = Σ Bᵢ(t) wᵢ",
  "negativeWeights.tex.poles": "(poli)",
  "negativeWeights.tex.noPole": "(nessun polo; ",
  "negativeWeights.tex.needs": " richiede ",
  "negativeWeights.tex.coefficients": "i coefficienti ",
  "negativeWeights.tex.sumToOne": " hanno somma 1: ",
  "negativeWeights.tex.staysInHull": " resta nell'inviluppo convesso; ",
  "negativeWeights.tex.breaks": " lo viola",
  "negativeWeights.aria":
    "Curva di Bézier razionale quadratica con P₀ = {p0}, P₁ = {p1}, P₂ = {p2} e pesi 1; {w}; 1: {verdict}; {poles}; {hull}; sotto, il grafico del denominatore w(t)",
  "negativeWeights.ariaRefused":
    "la libreria la rifiuta ({message}), la curva tratteggiata è la proiezione della curva omogenea data dalla formula",
  "negativeWeights.ariaAccepted": "la libreria la accetta",
  "negativeWeights.ariaPoles":
    "w(t) si annulla in t ≈ {list} ({count} in tutto): poli, dove la curva fugge all'infinito",
  "negativeWeights.ariaNoPoles": "w(t) resta positivo (valore minimo {min})",
  "negativeWeights.ariaOutside": "la curva esce dal suo inviluppo convesso",
  "negativeWeights.ariaInside": "la curva resta nel suo inviluppo convesso",
  "lagrange.title": "Interpolazione di Lagrange e triangolo di Aitken",
  "lagrange.summary":
    "Un solo polinomio per tutti i punti a confronto con una spline cubica; il triangolo di Aitken costruisce P(t) ed esce dall'inviluppo convesso; l'oscillazione cresce con il numero di punti.",
  "lagrange.aria":
    "Polinomio di Lagrange di grado {n} per {count} punti dati con parametri {params}, e la spline cubica naturale per gli stessi punti; t = {t}; P(t) = ({x}; {y}); la spline in t: ({sx}; {sy})",
  "lagrange.error.t": "campo “t”: {t} è fuori dal dominio del parametro [{a}; {b}] di questi punti",
  "lagrange.control.t": "Parametro t",
  "lagrange.control.t.input": "valore di t (decimale o frazione come 3/2)",
  "lagrange.control.stepBack.title": "t − 1/16 del dominio",
  "lagrange.control.step.title": "t + 1/16 del dominio",
  "lagrange.control.params": "Parametri tᵢ dei punti dati",
  "lagrange.params.uniform": "uniformi: tᵢ = i",
  "lagrange.params.chord": "lunghezza di corda: somme di |pᵢ₊₁ − pᵢ|",
  "lagrange.params.centripetal": "centripeti: somme di √|pᵢ₊₁ − pᵢ|",
  "lagrange.paramsName.uniform": "uniformi",
  "lagrange.paramsName.chord": "a lunghezza di corda",
  "lagrange.paramsName.centripetal": "centripeti",
  "lagrange.control.runge": "Esempio di Runge",
  "lagrange.control.count": "Punti equidistanti sulla campana di Runge",
  "lagrange.control.count.input": "numero di punti (da {min} a {max})",
  "lagrange.countRange":
    "il numero di punti deve essere un intero da {min} a {max}, ricevuto “{value}”",
  "lagrange.degree.many": "{count} punti: un polinomio di grado n = {n}",
  "lagrange.degree.one": "{count} punto: grado n = {n}",
  "lagrange.degree.other": "{count} punti: un polinomio di grado n = {n}",
  "lagrange.minPoints": "qui l'interpolazione di Lagrange richiede almeno {min} punti",
  "lagrange.maxPoints": "questa demo consente al massimo {max} punti",
  "lagrange.legendPolynomial": "polinomio di Lagrange P(t)",
  "lagrange.legendSpline": "spline cubica naturale S(t)",
  "lagrange.pointLabel": "P(t)",
  "lagrange.axisT": "t",
  "lagrange.marker": "t = {t}",
  "lagrange.sumNote": "Σ Lᵢ(t) = {sum}; qui ogni Lᵢ(t) ≥ 0",
  "lagrange.sumNegative":
    "Σ Lᵢ(t) = {sum}, ma L{i}(t) = {value} < 0: P(t) non è una combinazione convessa dei punti",
  "lagrange.colFunction": "Funzione di base",
  "lagrange.colParam": "tᵢ",
  "lagrange.colValue": "Lᵢ(t)",
  "lagrange.colPoint": "Punto dato pᵢ",
  "lagrange.sumRow": "Somma",
  "lagrange.basisCaption": "La base di Lagrange in t = {t}: il peso di ogni punto dato in P(t)",
  "lagrange.triangleCaption":
    "Il triangolo di Aitken in t = {t}: la riga r contiene i punti del livello r",
  "lagrange.tableLevel": "r = {r}",
  "lagrange.whatYouSee":
    "La curva blu è l'unico polinomio P(t) di grado n per tutti gli n + 1 punti dati; la curva verde è la spline cubica naturale per gli stessi punti con gli stessi parametri. I livelli colorati sono il triangolo di Aitken in t: ogni nuovo punto divide la retta del suo lato nel rapporto dei parametri, come in de Casteljau, ma cade fuori dal lato (punteggiato) quando t è fuori dall'intervallo dei parametri del lato, e le funzioni di base Lᵢ(t) sotto la figura hanno somma 1 ma diventano negative. Dalla parte sull'interpolazione delle dispense greche, sezione 5 del programma.",
  "lagrange.try1":
    "Porta “Punti equidistanti sulla campana di Runge” da 5 a 11: il polinomio oscilla sempre più ampiamente vicino agli estremi mentre la spline resta sulla campana.",
  "lagrange.try2":
    "Premi Avvia e osserva P(t) e il suo triangolo: tra i parametri dei dati i punti di un livello restano vicini ai loro lati, vicino agli estremi li superano di slancio.",
  "lagrange.try3":
    "Trascina p₂ verso l'alto: si muove l'intero polinomio, anche lontano da p₂, mentre la spline si muove soprattutto vicino a p₂. Poi scegli i parametri a lunghezza di corda e confronta.",
  "bezierPatch.title": "Patch di Bézier",
  "bezierPatch.summary":
    "Una patch bicubica con la sua rete di controllo 4 × 4: una curva generatrice che scorre lungo quattro direttrici, curve isoparametriche, la normale in un punto sonda, la forma matriciale.",
  "bezierPatch.aria":
    "Patch di Bézier bicubica con una rete di controllo 4 × 4; sonda in u = {u}; v = {v}; S(u, v) = ({x}; {y}; {z}); normale ({nx}; {ny}; {nz})",
  "bezierPatch.control.u": "Sonda u",
  "bezierPatch.control.u.input": "valore di u (decimale o frazione come 1/3)",
  "bezierPatch.control.v": "Sonda v e generatrice",
  "bezierPatch.control.v.input": "valore di v (decimale o frazione come 1/3)",
  "bezierPatch.control.stepBack.title": "v − 1/16",
  "bezierPatch.control.step.title": "v + 1/16",
  "bezierPatch.control.show": "Mostra",
  "bezierPatch.control.net": "Rete di controllo",
  "bezierPatch.control.iso": "Curve isoparametriche",
  "bezierPatch.control.wireframe": "Fil di ferro",
  "bezierPatch.control.sweep": "Generatrice e direttrici",
  "bezierPatch.control.normal": "Normale nella sonda",
  "bezierPatch.control.shading": "Ombreggiatura",
  "bezierPatch.shading.lit": "Illuminata",
  "bezierPatch.shading.zebra": "Strisce zebra",
  "bezierPatch.shading.gaussian": "Curvatura gaussiana K",
  "bezierPatch.shading.mean": "Curvatura media H",
  "bezierPatch.normalLabel": "n",
  "bezierPatch.texGeneratrix":
    "\\text{generatrice in } v = {v}\\text{: punti di controllo } D_i(v) = [v^3\\ v^2\\ v\\ 1]\\,M\\,[P_{i0}\\ P_{i1}\\ P_{i2}\\ P_{i3}]^T",
  "bezierPatch.whatYouSee":
    "Una patch di Bézier bicubica S(u, v) = Σ Σ B_i(u) B_j(v) P_ij sulla sua rete di controllo 4 × 4 (grigia, tratteggiata), illuminata dalle normali calcolate dal nucleo di calcolo. Come nelle dispense croate (sezione 6), ogni riga della rete definisce una direttrice D_i(v) (verde); per un dato v i loro punti D_0(v) … D_3(v) sono i punti di controllo della generatrice (vermiglia), una cubica in u che descrive la superficie al variare di v. Solo la prima e l'ultima direttrice giacciono sulla patch. La freccia è la normale unitaria nel punto sonda S(u, v). La forma matriciale scrive la patch come [u³ u² u 1] A [v³ v² v 1]ᵀ con A = M P Mᵀ, una matrice 4 × 4 per coordinata, calcolata dal nucleo di calcolo dalla rete attuale. Le strisce zebra riflettono bande di luce parallele sulla superficie; le ombreggiature di curvatura colorano ogni punto secondo K o H, blu negativo, bianco zero, vermiglio positivo, in scala rispetto al valore assoluto massimo sulla patch (gli estremi della legenda).",
  "bezierPatch.try1":
    "Premi Avvia accanto a v e osserva la generatrice percorrere la patch mentre i suoi punti di controllo scorrono lungo le direttrici.",
  "bezierPatch.try2":
    "Trascina un punto di controllo interno come P₁₁ (o selezionalo e premi PageUp): la superficie lo segue ma non lo raggiunge mai; trascina un angolo e la patch vi passa attraverso.",
  "bezierPatch.try3":
    "Ruota la figura (trascina lo spazio vuoto) finché guardi lungo un bordo della rete: la curva di bordo è la curva di Bézier dei quattro punti di quel bordo.",
  "bezierPatch.try4":
    "Scegli la curvatura gaussiana: le regioni blu sono a sella (K < 0), quelle vermiglie a cupola (K > 0). Trascina P₂₂ in alto e in basso e osserva i colori muoversi con il rilievo; passa alle strisce zebra e guardale piegarsi dove si piega la superficie.",
  "bezierPatch.try5":
    "Trascina un punto di controllo in una sola coordinata (selezionalo, usa le frecce) e osserva quali tra A_x, A_y, A_z cambiano: la forma matriciale è lineare nella rete, coordinata per coordinata.",
  "nurbsSurface.title": "Superfici B-spline e NURBS",
  "nurbsSurface.summary":
    "Una superficie B-spline a prodotto tensoriale con grado e nodi per ogni direzione: l'inserimento di nodi aggiunge un'intera riga o colonna di punti di controllo, i pesi attraggono la superficie, le cuciture colorate secondo la continuità misurata.",
  "nurbsSurface.aria":
    "Superficie B-spline con una rete di controllo {rows} × {cols}, gradi {p} in u e {q} in v; sonda in u = {u}; v = {v}: S = ({x}; {y}; {z}); {seams}",
  "nurbsSurface.control.u": "Sonda u",
  "nurbsSurface.control.u.input": "valore di u (decimale o frazione come 1/3)",
  "nurbsSurface.control.v": "Sonda v",
  "nurbsSurface.control.v.input": "valore di v (decimale o frazione come 1/3)",
  "nurbsSurface.control.directionU": "Direzione u (righe della rete)",
  "nurbsSurface.control.directionV": "Direzione v (colonne della rete)",
  "nurbsSurface.degree1": "1",
  "nurbsSurface.degree2": "2",
  "nurbsSurface.degree3": "3",
  "nurbsSurface.degree4": "4",
  "nurbsSurface.control.knotsU": "Nodi U",
  "nurbsSurface.control.knotsV": "Nodi V",
  "nurbsSurface.knotsHelp":
    "{count} nodi per {n} punti di controllo di grado {p}; digita un vettore e premi Invio",
  "nurbsSurface.control.insertU": "Inserisci u nella sonda (aggiunge una riga)",
  "nurbsSurface.control.insertV": "Inserisci v nella sonda (aggiunge una colonna)",
  "nurbsSurface.control.clamped": "Uniformi vincolati",
  "nurbsSurface.control.uniform": "Uniformi (non vincolati)",
  "nurbsSurface.control.weights": "Peso del punto selezionato (seleziona una maniglia)",
  "nurbsSurface.control.weight": "Peso di {name}",
  "nurbsSurface.control.weight.input": "peso del punto di controllo selezionato",
  "nurbsSurface.control.show": "Mostra",
  "nurbsSurface.control.net": "Rete di controllo",
  "nurbsSurface.control.iso": "Curve isoparametriche",
  "nurbsSurface.control.seams": "Cuciture per continuità",
  "nurbsSurface.control.normal": "Normale nella sonda",
  "nurbsSurface.control.shading": "Ombreggiatura",
  "nurbsSurface.shading.lit": "Illuminata",
  "nurbsSurface.shading.zebra": "Strisce zebra",
  "nurbsSurface.shading.gaussian": "Curvatura gaussiana K",
  "nurbsSurface.shading.mean": "Curvatura media H",
  "nurbsSurface.badWeight": "il peso “{value}” deve essere un numero in [{min}; {max}]",
  "nurbsSurface.badSelected":
    "campo “selected”: il punto {i} non esiste in una rete di {count} punti",
  "nurbsSurface.weightCount": "campo “weights”: {count} pesi per {points} punti di controllo",
  "nurbsSurface.netFull": "questa demo si ferma a {max} righe o colonne",
  "nurbsSurface.degreeTooHigh":
    "il grado {p} in {dir} richiede almeno {p} + 1 punti di controllo in quella direzione, la rete ne ha {count}",
  "nurbsSurface.insertedU":
    "Nodo u = {at} inserito: regola di Boehm su ogni colonna, ora la rete è {rows} × {cols}",
  "nurbsSurface.insertedV":
    "Nodo v = {at} inserito: regola di Boehm su ogni riga, ora la rete è {rows} × {cols}",
  "nurbsSurface.noSeams":
    "Nessun nodo interno: una sola patch polinomiale (o razionale), nessuna cucitura",
  "nurbsSurface.seamsReadout": "Cuciture misurate dal nucleo di calcolo: {u} · {v}",
  "nurbsSurface.legend": "Cuciture",
  "nurbsSurface.legendFreshRows": "nuove righe",
  "nurbsSurface.legendFreshColumns": "nuove colonne",
  "nurbsSurface.normalLabel": "n",
  "nurbsSurface.texNet":
    "\\text{rete } {rows} \\times {cols} = {count} \\text{ punti},\\ \\text{gradi } p = {p},\\ q = {q}\\text{: una cucitura in un nodo di molteplicità } r \\text{ è } C^{p-r}",
  "nurbsSurface.texInsertedU":
    "\\text{dopo } \\texttt{insertKnotU}\\text{: le righe } {first}\\text{–}{last} \\text{ sono nuove (Boehm su ogni colonna), una riga in più}",
  "nurbsSurface.texInsertedV":
    "\\text{dopo } \\texttt{insertKnotV}\\text{: le colonne } {first}\\text{–}{last} \\text{ sono nuove (Boehm su ogni riga), una colonna in più}",
  "nurbsSurface.whatYouSee":
    "Una superficie B-spline a prodotto tensoriale S(u, v) = Σ Σ N_i,p(u) N_j,q(v) P_ij (con pesi w_ij una superficie NURBS) sulla sua rete di controllo (grigia, tratteggiata). Ogni direzione ha il proprio grado e vettore dei nodi, e il dominio è [u_p, u_m+1] × [v_q, v_n+1]. Come dicono le dispense greche, si può inserire un nodo in ciascun vettore separatamente: inserire in u applica l'algoritmo di Boehm a ogni colonna della rete, il che aggiunge un'intera riga di punti di controllo senza cambiare la superficie (le righe create dalla regola di Boehm sono disegnate scure); in v agisce sulle righe e aggiunge una colonna. Le linee colorate sono le cuciture, le curve isoparametriche nei nodi interni, colorate secondo la continuità che il nucleo di calcolo misura attraverso di esse (C^(p−r) per un nodo di molteplicità r). Spostare un punto di controllo cambia la superficie solo su (p + 1) × (q + 1) intervalli: controllo locale. A differenza delle curve, le superfici non hanno la proprietà di diminuzione della variazione. La scelta Ombreggiatura mostra strisce zebra (una piega in esse è una rottura della continuità tangente) o la curvatura gaussiana o media, dalle derivate esatte del nucleo di calcolo.",
  "nurbsSurface.try1":
    "Premi “Inserisci u nella sonda”: compare una nuova riga di punti e la superficie resta esattamente dov'era; la legenda delle cuciture acquista il nuovo nodo.",
  "nurbsSurface.try2":
    "Digita 1 in Sonda u e inserisci: il nodo 1 ora è doppio, eppure la cucitura resta C², perché l'inserimento conserva la superficie. Ora trascina un punto delle nuove righe: la cucitura scende a C¹, tutto ciò che un nodo doppio garantisce con grado 3.",
  "nurbsSurface.try3":
    "Seleziona una maniglia interna e aumentane il peso: la superficie viene attratta verso di essa, e solo nelle sue vicinanze (controllo locale).",
  "nurbsSurface.try4":
    "Trascina un punto d'angolo, poi uno interno: la superficie vincolata passa per gli angoli ma mai per i punti interni.",
  "nurbsSurface.try5":
    "Passa una direzione a nodi uniformi (non vincolati): la superficie si ritira dal bordo della sua rete.",
  "surfaceInterpolation.title": "Interpolazione di superfici",
  "surfaceInterpolation.summary":
    "Una superficie B-spline per ogni punto di una griglia 4 × 5: parametri, nodi, poi ogni colonna interpolata in u e ogni riga del risultato in v.",
  "surfaceInterpolation.aria":
    "Superficie B-spline di gradi {p} e {q} per una griglia {rows} × {cols} di punti dati, parametri: {kind}; scarto massimo {miss}",
  "surfaceInterpolation.control.parametrisation": "Parametri",
  "surfaceInterpolation.kind.uniform": "Uniformi",
  "surfaceInterpolation.kind.chord": "Lunghezza di corda",
  "surfaceInterpolation.kind.centripetal": "Centripeti",
  "surfaceInterpolation.control.degreeU": "Grado p in u",
  "surfaceInterpolation.control.degreeV": "Grado q in v",
  "surfaceInterpolation.degree1": "1",
  "surfaceInterpolation.degree2": "2",
  "surfaceInterpolation.degree3": "3",
  "surfaceInterpolation.degree4": "4",
  "surfaceInterpolation.control.show": "Mostra",
  "surfaceInterpolation.control.columns": "Passo 1: ogni colonna interpolata in u",
  "surfaceInterpolation.control.net": "Rete di controllo del risultato",
  "surfaceInterpolation.control.iso": "Curve isoparametriche per i dati",
  "surfaceInterpolation.legendColumns": "passo 1: curve delle colonne, punti s_il",
  "surfaceInterpolation.legendNet": "rete di controllo P_ij",
  "surfaceInterpolation.missReadout":
    "La superficie passa per tutti i {count} punti dati: scarto massimo {miss}",
  "surfaceInterpolation.texUnknowns":
    "S(\\bar u_k, \\bar v_l) = Q_{kl},\\ k = 0..{m},\\ l = 0..{n}\\text{: } {rows} \\cdot {cols} = {count} \\text{ equazioni in } {count} \\text{ punti di controllo incogniti } P_{ij}\\ (p = {p},\\ q = {q})",
  "surfaceInterpolation.texColumns":
    "\\text{1. colonne: } {cols} \\text{ curve in } u\\ ({rows} \\times {rows}\\text{, } {cols} \\text{ termini noti})\\text{: } \\textstyle\\sum_i N_{i,{p}}(\\bar u_k)\\, s_{il} = Q_{kl}",
  "surfaceInterpolation.texRows":
    "\\text{2. righe: } {rows} \\text{ curve in } v\\ ({cols} \\times {cols}\\text{, } {rows} \\text{ termini noti})\\text{: } \\textstyle\\sum_j N_{j,{q}}(\\bar v_l)\\, P_{ij} = s_{il}",
  "surfaceInterpolation.whatYouSee":
    "Una griglia di 4 × 5 punti dati Q_kl (le maniglie, un campo di altezze) e la superficie B-spline che passa per ciascuno di essi. Ogni punto dato riceve i parametri (ū_k, v̄_l): lungo ogni colonna la parametrizzazione scelta (uniforme, a lunghezza di corda o centripeta) normalizzata su [0, 1], mediata sulle colonne, e allo stesso modo lungo le righe; i nodi sono medie dei parametri. Poi, come descrivono le dispense greche, il lavoro è in due passate di interpolazione di curve: prima ogni colonna dei dati è interpolata in u (le curve verdi e i loro punti di controllo s_il), poi ogni riga di quei punti di controllo è interpolata in v, il che dà la rete di controllo P_ij (viola, punteggiata). La curva isoparametrica della superficie in v̄_l è esattamente la curva verde della colonna l. La versione bicubica delle dispense aggiunge condizioni agli estremi (m + 3 punti di controllo per colonna); qui i nodi per media danno un punto di controllo per ogni punto dato. L'interpolazione è globale: trascinare un punto dato sposta l'intera rete.",
  "surfaceInterpolation.try1":
    "Attiva le curve isoparametriche: quelle in v̄_l giacciono esattamente sulle curve verdi delle colonne del passo 1, e quelle in ū_k attraversano le righe di dati.",
  "surfaceInterpolation.try2":
    "Trascina verso l'alto il punto dato più alto: la superficie passa ancora per ogni punto, ma la rete di controllo si muove ovunque — nessun controllo locale.",
  "surfaceInterpolation.try3":
    "Alterna parametri uniformi, a lunghezza di corda e centripeti dopo aver reso un intervallo della griglia molto più lungo degli altri: le oscillazioni si spostano.",
  "surfaceInterpolation.try4":
    "Imposta entrambi i gradi a 1: la superficie diventa le patch bilineari per la griglia, e la rete di controllo coincide con i dati.",
  "surfaceRevolution.title": "Rivoluzione, estrusione, superfici rigate",
  "surfaceRevolution.summary":
    "Superfici costruite da curve: un toro NURBS esatto, un vaso tornito da un profilo modificabile, un profilo estruso lungo un vettore, e la superficie rigata tra una quadratica e una cubica.",
  "surfaceRevolution.aria.torus":
    "Un toro (R = {R}; r = {r}) descritto ruotando di {angle}° una circonferenza NURBS esatta: una superficie razionale biquadratica con una rete di controllo {rows} × {cols}",
  "surfaceRevolution.aria.vase":
    "Un vaso: un profilo B-spline cubico di {count} punti nel piano xz ruotato di 360° attorno all'asse z; rete di controllo {rows} × {cols}",
  "surfaceRevolution.aria.extrude":
    "Il profilo B-spline cubico di {count} punti nel piano xy estruso lungo il vettore d; rete di controllo {rows} × {cols}",
  "surfaceRevolution.aria.ruled":
    "La superficie rigata tra una curva quadratica A e una curva cubica B, con le sue generatrici rettilinee; rete di controllo {rows} × {cols}",
  "surfaceRevolution.control.mode": "Superficie",
  "surfaceRevolution.mode.torus": "Toro (ruota una circonferenza)",
  "surfaceRevolution.mode.vase": "Vaso (ruota un profilo)",
  "surfaceRevolution.mode.extrude": "Estrudi il profilo",
  "surfaceRevolution.mode.ruled": "Superficie rigata tra due curve",
  "surfaceRevolution.control.R": "Distanza R della circonferenza dall'asse",
  "surfaceRevolution.control.R.input": "valore di R",
  "surfaceRevolution.control.r": "Raggio r della circonferenza",
  "surfaceRevolution.control.r.input": "valore di r",
  "surfaceRevolution.control.angle": "Angolo di rivoluzione (°)",
  "surfaceRevolution.control.angle.input": "angolo in gradi, fino a 360",
  "surfaceRevolution.control.show": "Mostra",
  "surfaceRevolution.minPoints": "il profilo richiede almeno {min} punti di controllo",
  "surfaceRevolution.maxPoints": "qui il profilo accetta al massimo {max} punti di controllo",
  "surfaceRevolution.control.net": "Rete di controllo della superficie",
  "surfaceRevolution.control.iso": "Curve isoparametriche",
  "surfaceRevolution.control.wireframe": "Fil di ferro",
  "surfaceRevolution.check.torus":
    "Rete {rows} × {cols}. Distanza massima dal toro sulla griglia di campioni del nucleo di calcolo: {distance} — esatta a meno di arrotondamenti.",
  "surfaceRevolution.check.vase":
    "Rete {rows} × {cols}. A ogni fotogramma di trascinamento la superficie viene ricostruita con sl.revolve ({revolve} ms) e trasformata in mesh ({mesh} ms).",
  "surfaceRevolution.check.extrude":
    "Rete {rows} × {cols}. S(u, 1) − S(u, 0) = {d} = d per ogni u.",
  "surfaceRevolution.check.ruled":
    "Rete {rows} × {cols}. S(u, ½) = {mid}, il punto medio di A(u) e B(u).",
  "surfaceRevolution.tex.circle":
    "C(v) = (R + r\\cos\\varphi,\\ 0,\\ r\\sin\\varphi),\\ R = {R},\\ r = {r}\\text{: la circonferenza NURBS esatta (9 punti)}",
  "surfaceRevolution.tex.revolve":
    "S(u, v) = \\mathrm{Rot}_z(u\\,\\theta)\\, C(v),\\ \\theta = {angle}^\\circ\\text{: rete } {rows} \\times {cols}\\text{, grado } 2 \\times 2\\text{ (A8.1)}",
  "surfaceRevolution.tex.weights": "\\text{pesi degli archi } w_{i0} = {weights}",
  "surfaceRevolution.tex.rational":
    "S(u, v) = \\frac{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij} P_{ij}}{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij}},\\quad w_{ij} = w_i\\, w_j",
  "surfaceRevolution.tex.torusCheck":
    "\\max_{{n} \\times {n}\\text{ griglia}} \\Bigl|\\sqrt{\\bigl(\\sqrt{x^2+y^2} - {R}\\bigr)^2 + z^2} - {r}\\Bigr| = {distance}\\text{: esatta}",
  "surfaceRevolution.tex.profile":
    "C(v) = \\sum_{j=0}^{{n}} N_{j,3}(v)\\,(x_j,\\ 0,\\ z_j)\\text{: cubica vincolata}",
  "surfaceRevolution.tex.revolveVase":
    "S(u, v) = \\bigl(x(v)\\cos 2\\pi u,\\ x(v)\\sin 2\\pi u,\\ z(v)\\bigr)\\text{: rete } {rows} \\times {cols}\\text{ (A8.1)}",
  "surfaceRevolution.tex.vaseNet":
    "P_{ij} = P_j\\text{ ruotato di } i \\cdot 45^\\circ\\text{, per } i\\text{ dispari spostato in fuori di } \\sqrt2\\ (1/\\cos 45^\\circ)",
  "surfaceRevolution.tex.extrude":
    "S(u, v) = C(u) + v\\,\\mathbf d,\\quad v \\in [0, 1],\\quad \\mathbf d = {d}",
  "surfaceRevolution.tex.extrudeNet":
    "P_{i0} = P_i,\\ P_{i1} = P_i + \\mathbf d\\text{: rete } {rows} \\times {cols}\\text{, grado 3 in } u\\text{, 1 in } v\\text{ (§10.3)}",
  "surfaceRevolution.tex.extrudeCheck": "S({u}, 1) - S({u}, 0) = {d}",
  "surfaceRevolution.tex.ruled":
    "S(u, v) = (1 - v)\\,A(u) + v\\,B(u),\\quad A\\text{ quadratica},\\ B\\text{ cubica}",
  "surfaceRevolution.tex.ruledNet":
    "\\text{prima compatibili: } A_i' = \\tfrac{i}{3} A_{i-1} + \\bigl(1 - \\tfrac{i}{3}\\bigr) A_i\\text{ (grado 2} \\to 3\\text{), rete } {rows} \\times {cols}\\text{ (§10.3)}",
  "surfaceRevolution.tex.ruledCheck": "A({u}) = {a},\\ B({u}) = {b},\\ S({u}, \\tfrac12) = {mid}",
  "surfaceRevolution.whatYouSee":
    "Superfici che il nucleo di calcolo costruisce da curve, ciascuna con la sua rete di controllo (grigia, tratteggiata) e le curve isoparametriche. La rivoluzione ruota una curva profilo attorno all'asse z: ogni punto di controllo Pⱼ diventa una circonferenza di 9 punti di controllo (quattro archi quadratici esatti, pesi 1, √2/2, 1, …), così un profilo circolare dà esattamente un toro e il vaso è esatto in ogni direzione attorno all'asse. L'estrusione trasla il profilo lungo un vettore d: due colonne, Pᵢ e Pᵢ + d. La superficie rigata unisce una quadratica A e una cubica B con segmenti rettilinei (le generatrici): il nucleo di calcolo prima eleva A al grado 3 così che entrambe abbiano stesso grado e stessi nodi.",
  "surfaceRevolution.try1":
    "Toro: porta l'angolo fino a 90° e osserva la rete passare da 9 righe a 3 (un arco); a 180°, 5.",
  "surfaceRevolution.try2":
    "Toro: la riga di verifica resta vicino a 10⁻¹⁶ per ogni R, r e angolo — una superficie razionale è esatta, una polinomiale potrebbe solo approssimare la circonferenza.",
  "surfaceRevolution.try3":
    "Vaso: trascina un punto del profilo; si muove solo nel piano xz, e l'intera superficie ruota con esso. Allontana P₀ dall'asse per aprire il fondo.",
  "surfaceRevolution.try4":
    "Estrusione: trascina la punta d della freccia per inclinare la parete; ogni generatrice dell'estrusione è una copia di d.",
  "surfaceRevolution.try5":
    "Rigata: confronta i quattro punti arancioni (la prima colonna della rete) con i tre punti di A — il nucleo di calcolo ha elevato A a una cubica con quattro punti che disegnano la stessa curva, così A e B possono condividere una sola rete.",
  "patchDeCasteljau.title": "De Casteljau su una patch",
  "patchDeCasteljau.summary":
    "Il punto S(u, v) di una patch di Bézier costruito solo con curve: de Casteljau su ogni riga in v, poi ancora una volta in u sui risultati. Partendo dalle colonne si ottiene lo stesso punto.",
  "patchDeCasteljau.aria":
    "Costruzione di de Casteljau su una patch di Bézier di grado {degree} × {degree}, {order}, passo {step} di {of}; u = {u}; v = {v}; S(u, v) = ({x}; {y}; {z})",
  "patchDeCasteljau.ariaRows": "prima le righe",
  "patchDeCasteljau.ariaColumns": "prima le colonne",
  "patchDeCasteljau.control.u": "u (il triangolo della colonna)",
  "patchDeCasteljau.control.u.input": "valore di u (decimale o frazione come 1/3)",
  "patchDeCasteljau.control.v": "v (il triangolo di ogni riga)",
  "patchDeCasteljau.control.v.input": "valore di v (decimale o frazione come 1/3)",
  "patchDeCasteljau.control.stepBackU.title": "u − 1/16",
  "patchDeCasteljau.control.stepU.title": "u + 1/16",
  "patchDeCasteljau.control.stepBackV.title": "v − 1/16",
  "patchDeCasteljau.control.stepV.title": "v + 1/16",
  "patchDeCasteljau.control.order": "Ordine",
  "patchDeCasteljau.control.rowsFirst": "Prima le righe (in v, poi u)",
  "patchDeCasteljau.control.columnsFirst": "Prima le colonne (in u, poi v)",
  "patchDeCasteljau.control.step": "Passo (livelli mostrati)",
  "patchDeCasteljau.control.step.input": "passo, un numero intero",
  "patchDeCasteljau.control.degree": "Grado della patch",
  "patchDeCasteljau.degree1": "1 × 1 (bilineare)",
  "patchDeCasteljau.degree2": "2 × 2 (biquadratica)",
  "patchDeCasteljau.degree3": "3 × 3 (bicubica)",
  "patchDeCasteljau.degree4": "4 × 4",
  "patchDeCasteljau.control.show": "Mostra",
  "patchDeCasteljau.control.surface": "Superficie",
  "patchDeCasteljau.control.net": "Rete di controllo",
  "patchDeCasteljau.pointLabel": "S(u, v)",
  "patchDeCasteljau.step.net": "Passo {k} di {of}: solo la rete di controllo.",
  "patchDeCasteljau.step.rows":
    "Passo {k} di {of}: livello {r} del triangolo di de Casteljau di ogni riga in v = {v}.",
  "patchDeCasteljau.step.columns":
    "Passo {k} di {of}: livello {r} del triangolo di de Casteljau di ogni colonna in u = {u}.",
  "patchDeCasteljau.step.rowResults":
    "Passo {k} di {of}: i {count} risultati delle righe Q₀ … sono i punti di controllo della curva isoparametrica in v = {v}.",
  "patchDeCasteljau.step.columnResults":
    "Passo {k} di {of}: i {count} risultati delle colonne R₀ … sono i punti di controllo della curva isoparametrica in u = {u}.",
  "patchDeCasteljau.step.column":
    "Passo {k} di {of}: livello {r} di de Casteljau su Q₀ … in u = {u}.",
  "patchDeCasteljau.step.row": "Passo {k} di {of}: livello {r} di de Casteljau su R₀ … in v = {v}.",
  "patchDeCasteljau.step.point":
    "Passo {k} di {of}: il vertice dell'ultimo triangolo è il punto S(u, v) della patch.",
  "patchDeCasteljau.step.pointColumns":
    "Passo {k} di {of}: il vertice dell'ultimo triangolo è il punto S(u, v) della patch.",
  "patchDeCasteljau.texRows":
    "\\text{ogni riga } i\\text{ in } v = {v}\\text{:}\\ \\ P_{ij}^{r} = (1-v)\\,P_{ij}^{r-1} + v\\,P_{i,j+1}^{r-1},\\quad Q_i = P_{i0}^{{n}}",
  "patchDeCasteljau.texColumn":
    "\\text{poi in } u = {u}\\text{:}\\ \\ Q_{i}^{r} = (1-u)\\,Q_{i}^{r-1} + u\\,Q_{i+1}^{r-1},\\quad S(u, v) = Q_0^{{m}}",
  "patchDeCasteljau.texColumns":
    "\\text{ogni colonna } j\\text{ in } u = {u}\\text{:}\\ \\ P_{ij}^{r} = (1-u)\\,P_{ij}^{r-1} + u\\,P_{i+1,j}^{r-1},\\quad R_j = P_{0j}^{{m}}",
  "patchDeCasteljau.texRow":
    "\\text{poi in } v = {v}\\text{:}\\ \\ R_{j}^{r} = (1-v)\\,R_{j}^{r-1} + v\\,R_{j+1}^{r-1},\\quad S(u, v) = R_0^{{n}}",
  "patchDeCasteljau.texBoth":
    "S({u}; {v}) = \\underbrace{{rows}}_{\\text{prima le righe}} = \\underbrace{{columns}}_{\\text{prima le colonne}},\\quad \\lvert\\Delta\\rvert = {gap}",
  "patchDeCasteljau.whatYouSee":
    "Le dispense greche calcolano un punto di una superficie di Bézier solo con curve. L'algoritmo di de Casteljau viene eseguito su ogni riga della rete di controllo rispetto a v (i colori dei livelli della demo sulle curve); dà m + 1 punti Q₀ … Qₘ (vermigli), i punti di controllo della curva isoparametrica corrispondente a v (la curva vermiglia sulla patch). Ancora de Casteljau su questi punti, rispetto a u, termina nel punto S(u, v). Partendo dalle colonne (ogni colonna in u, poi la riga dei risultati in v) si termina nello stesso punto: la formula mostra entrambi.",
  "patchDeCasteljau.try1":
    "Imposta il passo a 0 e aumentalo uno alla volta: i livelli delle righe, i loro risultati sulla curva isoparametrica, poi l'ultimo triangolo fino a S(u, v).",
  "patchDeCasteljau.try2":
    "Passa a “Prima le colonne”: i triangoli si girano dall'altra parte e la curva isoparametrica corre trasversalmente, eppure S(u, v) resta dov'era.",
  "patchDeCasteljau.try3":
    "Premi Avvia accanto a v: i risultati delle righe scorrono lungo le curve di Bézier delle righe e la loro curva isoparametrica percorre la patch.",
  "patchDeCasteljau.try4":
    "Trascina un punto interno come P₁₁: cambia ogni triangolo della sua riga, i triangoli delle altre righe restano.",
  "patchDeCasteljau.try5":
    "Scegli il grado 1 × 1: un livello per direzione, e S(u, v) è l'interpolazione bilineare dei quattro angoli.",
  "patchSubdivision.title": "Suddivisione di una patch",
  "patchSubdivision.summary":
    "Una patch bicubica divisa in (u₀, v₀) in quattro patch dello stesso grado, e disegnata in modo adattivo: dividi ancora finché ogni rete è abbastanza piatta.",
  "patchSubdivision.ariaSplit":
    "Patch di Bézier bicubica divisa in u₀ = {u}; v₀ = {v} in quattro patch con le loro reti, che si incontrano in S(u₀, v₀) = ({x}; {y}; {z})",
  "patchSubdivision.ariaAdaptive":
    "Patch di Bézier bicubica tassellata in modo adattivo con tolleranza {tolerance}: {triangles} triangoli; una griglia uniforme fine come la cella più fine ne ha {uniform}",
  "patchSubdivision.control.mode": "Mostra",
  "patchSubdivision.control.split": "Dividi in (u₀, v₀)",
  "patchSubdivision.control.adaptive": "Tassellazione adattiva",
  "patchSubdivision.control.u0": "u₀",
  "patchSubdivision.control.u0.input": "valore di u₀ (decimale o frazione come 1/3)",
  "patchSubdivision.control.v0": "v₀",
  "patchSubdivision.control.v0.input": "valore di v₀ (decimale o frazione come 1/3)",
  "patchSubdivision.control.nets": "Le quattro reti di controllo",
  "patchSubdivision.control.tolerance": "Tolleranza ε (unità del modello)",
  "patchSubdivision.control.tolerance.input": "tolleranza ε, da {min} a {max}",
  "patchSubdivision.badTolerance":
    "tolleranza ε: “{value}” non è un numero da {min} a {max}; resta il valore attuale",
  "patchSubdivision.control.quadtree": "Il quadtree nel quadrato (u, v)",
  "patchSubdivision.splitNote":
    "Quattro patch bicubiche su [0, {u}] × [0, {v}] (arancione), [0, {u}] × [{v}, 1] (verde), [{u}, 1] × [0, {v}] (viola) e [{u}, 1] × [{v}, 1] (vermiglio).",
  "patchSubdivision.counts":
    "{triangles} triangoli con ε = {tolerance}; una griglia uniforme {n} × {n}, fine ovunque come la cella più fine, ne ha {uniform}.",
  "patchSubdivision.pointLabel": "S(u₀, v₀)",
  "patchSubdivision.axisU": "u",
  "patchSubdivision.axisV": "v",
  "patchSubdivision.texPieces":
    "\\text{quattro patch su }[0,u_0]\\times[0,v_0],\\ [0,u_0]\\times[v_0,1],\\ [u_0,1]\\times[0,v_0],\\ [u_0,1]\\times[v_0,1]",
  "patchSubdivision.texPoint": "u_0 = {u},\\ v_0 = {v}\\text{:}\\quad S(u_0, v_0) = {point}",
  "patchSubdivision.texCorner":
    "\\text{angolo comune: } P^{(1)}_{33} = P^{(2)}_{30} = P^{(3)}_{03} = P^{(4)}_{00} = {corner},\\quad \\max\\lvert P - S(u_0, v_0)\\rvert = {gap}",
  "patchSubdivision.texFlat":
    "\\text{rete piatta: } 2\\delta + \\tfrac{1}{4}\\lvert D\\rvert \\le \\varepsilon = {tolerance} \\;\\Rightarrow\\; \\text{disegna il quadrilatero degli angoli, altrimenti dividi in } (\\tfrac12, \\tfrac12)",
  "patchSubdivision.texCounts":
    "\\text{{triangles} triangoli}\\quad\\text{rispetto a}\\quad 2 \\cdot {n}^2 = {uniform} \\text{ su una griglia uniforme fine come la cella più fine}",
  "patchSubdivision.whatYouSee":
    "Le dispense greche suddividono una superficie di Bézier come una curva: scegli una coppia (u₀, v₀); de Casteljau su ogni riga della rete divide la curva di ogni riga in una parte “sinistra” e una “destra”; de Casteljau sulle colonne di entrambe le parti divide ciascuna in una parte “superiore” e una “inferiore”. Il risultato sono quattro patch dello stesso tipo, ciascuna con la propria rete (m + 1) × (n + 1) (i quattro colori); insieme formano la patch, e si incontrano in S(u₀, v₀). In “Tassellazione adattiva” si applica la regola di disegno delle dispense: se i punti di controllo sono (quasi) complanari, disegna il quadrilatero dei quattro punti d'angolo, altrimenti suddividi in quattro e ripeti per ogni pezzo. Qui “quasi” è misurato rispetto alla tolleranza ε (δ limita la distanza della rete dalla patch bilineare dei suoi angoli, D è la sua torsione), così ogni punto di ogni triangolo dista meno di ε dalla superficie. Il riquadro mostra le celle nel quadrato (u, v).",
  "patchSubdivision.try1":
    "Muovi u₀ e v₀: le quattro reti cambiano, ma il loro angolo comune giace sempre sulla patch, in S(u₀, v₀).",
  "patchSubdivision.try2":
    "Trascina u₀ a 0: due pezzi si riducono a curve (le loro reti collassano sul bordo).",
  "patchSubdivision.try3":
    "Passa a “Tassellazione adattiva” e diminuisci ε: le celle si dividono dove la patch si piega, e restano grandi dove è quasi piatta.",
  "patchSubdivision.try4":
    "In “Tassellazione adattiva”, trascina il rilievo P₂₂ fino al piano dei suoi vicini: le celle piccole attorno si fondono in celle grandi.",
  "patchSubdivision.try5":
    "Confronta il numero di triangoli con una griglia uniforme fine come la cella più fine: la mesh adattiva spende i suoi triangoli solo dove la patch si piega.",
  "hermite.title": "Interpolazione cubica di Hermite",
  "hermite.summary":
    "Un pezzo cubico tra due punti dati ottenuto dai punti e dalle loro tangenti; i pezzi che condividono le tangenti si uniscono C¹, una tangente sbloccata solo G¹.",
  "hermite.aria":
    "Curva di Hermite cubica a tratti per {count} punti dati; t = {t}; P(t) = ({x}; {y}); giunzioni: {joints}",
  "hermite.whatYouSee":
    "La curva blu passa per i punti dati P₀ … Pₙ in t = 0, 1, 2, …; in ogni punto una freccia arancione mostra la sua tangente m (disegnata a metà della lunghezza; trascinane la punta). Tra Pᵢ e Pᵢ₊₁ la curva è H₀·Pᵢ + H₁·Pᵢ₊₁ + H₂·Δmᵢ + H₃·Δmᵢ₊₁, con le quattro funzioni di base di Hermite tracciate sotto (sezione 5 del programma, dal capitolo sull'interpolazione delle dispense greche e dalle dispense croate). Condividere una tangente per punto rende la curva C¹; la verifica di continuità del nucleo di calcolo indica il tipo di ogni giunzione.",
  "hermite.try1":
    "Premi Avvia e osserva il marcatore scorrere lungo H₀ … H₃ sotto: in u = 1/2 la tabella indica H₀ = H₁ = 1/2 e H₂ = −H₃ = 1/8.",
  "hermite.try2":
    "Trascina la punta della freccia tangente in P₁: cambiano solo i due pezzi che si incontrano in P₁, e la giunzione resta C¹.",
  "hermite.try3":
    "Spunta “Sblocca la tangente”, poi trascina la freccia viola entrante o muovi λ: la giunzione diventa “solo G¹” — stessa direzione, velocità diversa.",
  "hermite.minPoints": "l'interpolazione di Hermite richiede almeno {min} punti dati",
  "hermite.maxPoints": "questa demo consente al massimo {max} punti dati",
  "hermite.count": "{count} punti dati, {pieces} pezzi cubici",
  "hermite.local": "Pezzo {i}: u = {u} (Δ = {delta})",
  "hermite.control.tangent": "Tangente m{i} del punto selezionato (x y)",
  "hermite.badTangent": "una tangente è una coppia di numeri come “3 -1/2”, ricevuto “{value}”",
  "hermite.control.bezier": "Mostra la forma di Bézier del pezzo attuale",
  "hermite.control.joinLegend": "Giunzioni",
  "hermite.control.unlocked": "Sblocca la tangente in un punto interno (G¹)",
  "hermite.control.joint": "Punto sbloccato k",
  "hermite.control.joint.input": "indice k del punto sbloccato",
  "hermite.control.ratio": "λ = |m⁻| / |m⁺|",
  "hermite.control.ratio.input":
    "rapporto λ tra le lunghezze della tangente entrante e di quella uscente",
  "hermite.joints": "Verifica del nucleo di calcolo nelle giunzioni: {list}",
  "hermite.noJoints": "Un solo pezzo: nessuna giunzione da verificare",
  "hermite.g1Only": "solo G¹",
  "hermite.c0Only": "solo C⁰",
  "hermite.marker": "u = {u}",
  "hermite.formula.checker": "verifica del nucleo di calcolo:",
  "hermite.col.function": "Funzione",
  "hermite.col.polynomial": "Polinomio",
  "hermite.col.value": "Valore in u",
  "hermite.col.times": "Moltiplica",
  "hermite.tableCaption": "La base di Hermite in u = {u} (pezzo {i})",
  "cardinal.title": "Spline cardinali e Catmull–Rom",
  "cardinal.summary":
    "Tangenti scelte automaticamente dai vicini: una tensione c le appiattisce; l'α di Catmull–Rom (uniforme, centripeta, corda) decide se un segmento corto forma un cappio.",
  "cardinal.aria": "Curva di tipo {mode}, {value}, per {count} punti dati; {loop}",
  "cardinal.whatYouSee":
    "Una curva di Hermite per i punti dati le cui tangenti (arancioni, disegnate come le maniglie di Bézier Δ·m/3) derivano dai punti vicini (sezione 5 del programma; le dispense croate danno la forma matriciale di Catmull–Rom mostrata nel pannello della formula). In modalità cardinale la tensione c le riduce; in modalità Catmull–Rom i passi del parametro sono |Pᵢ₊₁ − Pᵢ|^α. I punti sono distanziati in modo irregolare, quindi la Catmull–Rom uniforme (α = 0, tratteggiata) forma un cappio nel segmento corto P₁P₂, mentre quella centripeta (α = ½) no.",
  "cardinal.try1":
    "Porta α da 0,5 fino a 0: la curva continua diventa quella tratteggiata e appare il cappio nel segmento 1; con α = 1 (lunghezza di corda) aderisce al poligono.",
  "cardinal.try2":
    "Passa a cardinale e porta la tensione c verso 1: le tangenti si annullano e la curva diventa il poligono; con c < 0 produce sovraelongazioni (overshoot).",
  "cardinal.try3":
    "Allontana P₂ da P₁ finché i segmenti hanno circa la stessa lunghezza: il cappio della curva uniforme scompare — cuspidi e cappi nascono dalla spaziatura irregolare.",
  "cardinal.minPoints": "questa demo richiede almeno {min} punti dati",
  "cardinal.maxPoints": "questa demo consente al massimo {max} punti dati",
  "cardinal.count": "{count} punti dati",
  "cardinal.control.modeLegend": "Tangenti",
  "cardinal.mode.cardinal": "cardinale (tensione c)",
  "cardinal.mode.catmull-rom": "Catmull–Rom (α)",
  "cardinal.control.tension": "Tensione c",
  "cardinal.control.tension.input": "tensione c (da −1 a 1)",
  "cardinal.control.alpha": "α (0 uniforme, ½ centripeta, 1 corda)",
  "cardinal.control.alpha.input": "esponente α (da 0 a 1)",
  "cardinal.control.closed": "Curva chiusa",
  "cardinal.control.segment": "Segmento i (da Pᵢ a Pᵢ₊₁)",
  "cardinal.control.segment.input": "indice del segmento i",
  "cardinal.loopHere": "Questa curva forma un cappio nel segmento {i}.",
  "cardinal.loopGhost":
    "La curva uniforme (α = 0, tratteggiata) forma un cappio nel segmento {i}; questa no.",
  "cardinal.noLoopHere": "Nessun cappio all'interno di un segmento.",
  "cardinal.noLoopGhost": "Nessun cappio all'interno di un segmento, nemmeno per α = 0.",
  "cardinal.loopLabel": "cappio",
  "cardinal.legend.curve": "questa curva",
  "cardinal.legend.ghost": "uniforme, α = 0",
  "cardinal.formula.ghost": "(α = 0: la curva tratteggiata)",
  "cardinal.col.point": "Punto",
  "cardinal.col.param": "Parametro tᵢ",
  "cardinal.col.tangent": "Tangente mᵢ (nucleo di calcolo)",
  "cardinal.tableCaption": "Parametri e tangenti nei punti dati",
  "cubicSpline.title": "Spline cubiche C2: condizioni agli estremi",
  "cubicSpline.summary":
    "Condizioni agli estremi naturale, vincolata, quadratica, di Bessel, not-a-knot e periodica sugli stessi punti: il sistema tridiagonale, C″ e C‴ per ogni pezzo",
  "cubicSpline.aria":
    "Spline cubica C2 per {count} punti, condizione agli estremi {end}, parametri {parametrization}; tangenti agli estremi m₀ = {m0}, mₙ = {mn}",
  "cubicSpline.whatYouSee":
    "Una spline cubica C2 per i punti: un pezzo cubico di Hermite tra punti vicini, con le tangenti mᵢ ricavate da un sistema tridiagonale che rende C″ continua in ogni punto interno, più un'equazione a ciascun estremo — la condizione agli estremi. La tabella mostra quel sistema con i numeri attuali, con le righe degli estremi evidenziate; i grafici sotto la figura mostrano C″ (continua nelle giunzioni) e C‴ (che vi salta) pezzo per pezzo. Dall'interpolazione cubica di Hermite delle dispense greche (sezione 5 del programma), dove le righe dell'estremo finale delle condizioni naturale e quadratica sono stampate con fattori sbagliati: le righe qui sono ricavate.",
  "cubicSpline.try1":
    "Scegli naturale e guarda il grafico di C″: entrambe le componenti sono 0 nella prima e nell'ultima giunzione. Poi scegli quadratica: C‴ è 0 sul primo e sull'ultimo pezzo (sono parabole), e la prima riga della tabella diventa 1, 1 | 2(p₁ − p₀)/Δ₀.",
  "cubicSpline.try2":
    "Scegli not-a-knot e osserva il grafico di C‴: i salti in t₁ e tₙ₋₁ sono spariti, quindi i primi due e gli ultimi due pezzi sono un'unica cubica ciascuno. Scegli vincolata e trascina le frecce in P₀ e Pₙ.",
  "cubicSpline.try3":
    "Spunta “Sovrapponi tutte e sei” e trascina un punto al centro: lontano dagli estremi le sei curve coincidono, vicino agli estremi si separano. Passa ai parametri a lunghezza di corda e trascina un punto vicino al suo vicino.",
  "cubicSpline.minPoints": "qui una spline richiede almeno {min} punti",
  "cubicSpline.maxPoints": "questa demo consente al massimo {max} punti",
  "cubicSpline.pointCount.many": "{count} punti, n = {n}",
  "cubicSpline.pointCount.one": "{count} punto",
  "cubicSpline.pointCount.other": "{count} punti, n = {n}",
  "cubicSpline.control.end": "Condizione agli estremi",
  "cubicSpline.control.compare": "Sovrapponi tutte e sei",
  "cubicSpline.control.parametrization": "Parametri tᵢ",
  "cubicSpline.control.third": "Traccia anche C‴",
  "cubicSpline.end.natural": "naturale",
  "cubicSpline.end.clamped": "vincolata",
  "cubicSpline.end.quadratic": "quadratica",
  "cubicSpline.end.bessel": "Bessel",
  "cubicSpline.end.not-a-knot": "not-a-knot",
  "cubicSpline.end.periodic": "periodica",
  "cubicSpline.parametrization.uniform": "uniformi",
  "cubicSpline.parametrization.chord": "a lunghezza di corda",
  "cubicSpline.parametrization.centripetal": "centripeti",
  "cubicSpline.closingLabel": "P₀ = P{n}",
  "cubicSpline.tipStart": "m₀",
  "cubicSpline.tipEnd": "mₙ",
  "cubicSpline.plotNote":
    "C″(t₀) = {secondStart}, C″(t{n}) = {secondEnd}; C‴ = {thirdFirst} sul primo pezzo, {thirdLast} sull'ultimo; C‴ salta in {jumps}",
  "cubicSpline.noJumps": "nessuna giunzione",
  "cubicSpline.plotX": "x",
  "cubicSpline.plotY": "y",
  "cubicSpline.plotSecond": "C″(t)",
  "cubicSpline.plotThird": "C‴(t)",
  "cubicSpline.tex.params": "parametri:",
  "cubicSpline.tex.given": "assegnata",
  "cubicSpline.tex.arrow": "la freccia in",
  "cubicSpline.tex.parabola": "la parabola per",
  "cubicSpline.tex.continuous": "continua in",
  "cubicSpline.tex.start": "inizio",
  "cubicSpline.tex.end": "fine",
  "cubicSpline.row.interior": "C″ continua in t{i}",
  "cubicSpline.row.start.natural": "C″(t₀) = 0: 2m₀ + m₁ = 3(p₁ − p₀)/Δ₀",
  "cubicSpline.row.end.natural": "C″(t{n}) = 0: m{a} + 2m{n} = 3(p{n} − p{a})/Δ{a}",
  "cubicSpline.row.start.quadratic": "C″(t₀) = C″(t₁): m₀ + m₁ = 2(p₁ − p₀)/Δ₀",
  "cubicSpline.row.end.quadratic": "C″(t{a}) = C″(t{n}): m{a} + m{n} = 2(p{n} − p{a})/Δ{a}",
  "cubicSpline.row.start.clamped": "m₀ assegnata (la freccia in P₀)",
  "cubicSpline.row.end.clamped": "m{n} assegnata (la freccia in P{n})",
  "cubicSpline.row.start.bessel": "m₀ = la tangente della parabola per p₀, p₁, p₂",
  "cubicSpline.row.end.bessel": "m{n} = la tangente della parabola per p{c}, p{a}, p{n}",
  "cubicSpline.row.start.not-a-knot": "not-a-knot: C‴ continua in t₁",
  "cubicSpline.row.end.not-a-knot": "not-a-knot: C‴ continua in t{a}",
  "cubicSpline.row.start.periodic": "periodica: C″ continua in t₀ = t{n}",
  "cubicSpline.row.end.periodic": "C″ continua in t{last}, m{n} = m₀",
  "cubicSpline.systemEquation": "Equazione",
  "cubicSpline.systemUnknown": "mᵢ",
  "cubicSpline.systemRhs": "cᵢ",
  "cubicSpline.tableCaption":
    "Il sistema tridiagonale A·m = c ({size} equazioni) per le tangenti mᵢ = C′(tᵢ), condizione agli estremi {end}, parametri {parametrization}; le righe degli estremi sono evidenziate{hidden}",
  "cubicSpline.tableCaptionCyclic":
    "Il sistema tridiagonale ciclico A·m = c ({size} equazioni) per le tangenti mᵢ = C′(tᵢ), condizione agli estremi {end}, parametri {parametrization}; le righe degli estremi sono evidenziate, gli angoli incorniciati{hidden}",
  "cubicSpline.tableHidden": " ({count} righe e colonne centrali omesse: ⋮, ⋯)",
  "parametrization.title": "Parametrizzazione: uniforme, lunghezza di corda, centripeta",
  "parametrization.summary":
    "Gli stessi punti interpolati con parametri uniformi, a lunghezza di corda e centripeti, con la velocità e le tacche dei parametri di ogni curva: una spaziatura irregolare fa produrre sovraelongazioni (overshoot) alla curva uniforme.",
  "parametrization.aria":
    "{method} per {count} punti dati con parametri uniformi, a lunghezza di corda, centripeti e α = {alpha}; in s = {s}: uniforme {uniform}, corda {chord}, centripeta {centripetal}; le loro velocità sono tracciate sotto",
  "parametrization.control.s": "Parametro normalizzato s",
  "parametrization.control.s.input": "valore di s da 0 a 1 (decimale o frazione)",
  "parametrization.control.alphaGroup": "Una quarta curva: tᵢ₊₁ = tᵢ + |pᵢ₊₁ − pᵢ|^α",
  "parametrization.control.alpha": "Esponente α",
  "parametrization.control.alpha.input": "α da 0 a 1",
  "parametrization.control.alphaCurve": "Mostra la curva α (arancione, tratto-punto)",
  "parametrization.alphaIs.uniform": "α = {alpha}: i parametri uniformi (sulla curva blu)",
  "parametrization.alphaIs.chord":
    "α = {alpha}: i parametri a lunghezza di corda (sulla curva verde)",
  "parametrization.alphaIs.centripetal": "α = {alpha}: i parametri centripeti (sulla curva viola)",
  "parametrization.alphaBetween": "α = {alpha}: 0 è uniforme, 0,5 centripeta, 1 lunghezza di corda",
  "parametrization.control.method": "Curva interpolante",
  "parametrization.method.cubic": "Spline cubica naturale C²",
  "parametrization.method.catmull-rom": "Spline di Catmull–Rom (C¹)",
  "parametrization.methodName.cubic": "spline cubiche naturali",
  "parametrization.methodName.catmull-rom": "spline di Catmull–Rom",
  "parametrization.minPoints": "qui una spline interpolante richiede almeno {min} punti",
  "parametrization.maxPoints": "questa demo consente al massimo {max} punti",
  "parametrization.legend.uniform": "uniforme (α = 0)",
  "parametrization.legend.chord": "corda (α = 1)",
  "parametrization.legend.centripetal": "centripeta (α = ½)",
  "parametrization.legend.alpha": "α del cursore",
  "parametrization.marker": "s = {s}",
  "parametrization.axisSpeed": "velocità |dC/ds|",
  "parametrization.axisS": "s = (t − t₀)/(tₙ − t₀)",
  "parametrization.tex.uniform": "uniforme",
  "parametrization.tex.chord": "corda",
  "parametrization.tex.centripetal": "centripeta",
  "parametrization.tableCaption":
    "I lati del poligono dei dati e i parametri tᵢ di ogni parametrizzazione",
  "parametrization.colKind": "i",
  "parametrization.rowLegs": "|pᵢ₊₁ − pᵢ|",
  "parametrization.row.uniform": "tᵢ uniformi",
  "parametrization.row.chord": "tᵢ a lunghezza di corda",
  "parametrization.row.centripetal": "tᵢ centripeti",
  "parametrization.row.alpha": "α = {alpha}: tᵢ",
  "parametrization.whatYouSee":
    "Quattro curve interpolanti per gli stessi punti, che differiscono solo nei parametri tᵢ assegnati ai punti: uniformi (blu, continua), a lunghezza di corda (verde, tratteggiata), centripeti (viola, punteggiata) e un α qualsiasi dal cursore (arancione, tratto-punto). Sotto la figura, la velocità di ogni curva rispetto al parametro normalizzato s, e una riga di tacche per curva dove cadono i suoi parametri dei dati. I parametri uniformi danno a un lato lungo tanto parametro quanto a uno corto, così la curva corre lungo il lato lungo e va oltre o forma cappi in quelli corti. Dalla parte sull'interpolazione delle dispense greche, sezione 5 del programma.",
  "parametrization.try1":
    "Premi Avvia: i quattro punti partono e arrivano insieme, ma quello blu (uniforme) corre lungo i lati lunghi mentre quello verde (corda) tiene un passo quasi costante — confronta i loro grafici della velocità.",
  "parametrization.try2":
    "Porta α da 0 a 1: la curva arancione passa per quella blu (α = 0), quella viola (α = 0,5) e quella verde (α = 1), e le sue tacche si spostano con essa.",
  "parametrization.try3":
    "Trascina p₃ vicino a p₂ così che un lato sia molto corto: lì la curva uniforme forma un cappio, quella centripeta no. Poi passa a Catmull–Rom e fai lo stesso.",
  "bsplineInterpolation.title": "Interpolazione con B-spline",
  "bsplineInterpolation.summary":
    "Una B-spline di grado qualsiasi per punti assegnati, con derivate agli estremi facoltative: i punti di controllo risolvono un sistema lineare quadrato, mostrato con i suoi numeri.",
  "bsplineInterpolation.aria":
    "B-spline {kind} per {count} punti dati con parametri {params}, {ends}; il sistema ha {size} incognite (punti di controllo r); nodi {knots}",
  "bsplineInterpolation.aria.start": "derivata iniziale D₀ assegnata",
  "bsplineInterpolation.aria.end": "derivata finale assegnata",
  "bsplineInterpolation.aria.noEnds": "nessuna derivata agli estremi",
  "bsplineInterpolation.degreeLegend": "Grado p",
  "bsplineInterpolation.degreeOption": "{p}",
  "bsplineInterpolation.minPoints":
    "il grado {degree} richiede almeno {min} condizioni (punti dati e derivate agli estremi insieme)",
  "bsplineInterpolation.error.degree":
    "il campo “degree” vale {p}, ma {count} condizioni (punti dati e derivate agli estremi) consentono al massimo il grado {max}",
  "bsplineInterpolation.maxPoints": "questa demo consente al massimo {max} punti dati",
  "bsplineInterpolation.paramsLegend": "Parametri tᵢ",
  "bsplineInterpolation.params.uniform": "uniformi",
  "bsplineInterpolation.params.chord": "a lunghezza di corda",
  "bsplineInterpolation.params.centripetal": "centripeti",
  "bsplineInterpolation.paramsNote": "t = {list}",
  "bsplineInterpolation.derivativesLegend":
    "Derivate agli estremi (trascina le punte delle frecce)",
  "bsplineInterpolation.control.start": "Inizio: C′(t₀) = D₀",
  "bsplineInterpolation.control.end": "Fine: C′(tₙ) = Dₙ",
  "bsplineInterpolation.startValue": "D₀ = {xy}",
  "bsplineInterpolation.endValue": "D{n} = {xy}",
  "bsplineInterpolation.noDerivatives":
    "nessuna condizione sulle derivate: solo una per punto dato",
  "bsplineInterpolation.legendCurve": "C(u), per i punti dati pᵢ",
  "bsplineInterpolation.legendPolygon": "poligono di controllo rⱼ (calcolato)",
  "bsplineInterpolation.legendDerivative": "derivata all'estremo D = C′(t), lunghezza intera",
  "bsplineInterpolation.startLabel": "D₀",
  "bsplineInterpolation.endLabel": "Dₙ",
  "bsplineInterpolation.control.notesKnots": "I nodi delle dispense 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.knotsNotes": "Nodi U = {list} (la scelta delle dispense)",
  "bsplineInterpolation.knotsDefault":
    "Nodi U = {list} (la scelta predefinita del nucleo di calcolo: parametri mediati)",
  "bsplineInterpolation.sizeNote": "{points} e le derivate danno {unknowns}",
  "bsplineInterpolation.dataPoints.many": "{count} punti dati",
  "bsplineInterpolation.dataPoints.one": "{count} punto dato",
  "bsplineInterpolation.dataPoints.other": "{count} punti dati",
  "bsplineInterpolation.controlPoints.many": "{count} punti di controllo",
  "bsplineInterpolation.controlPoints.one": "{count} punto di controllo",
  "bsplineInterpolation.controlPoints.other": "{count} punti di controllo",
  "bsplineInterpolation.notesExample": "Esempio croato",
  "bsplineInterpolation.notesExample.title":
    "Torna all'esempio svolto delle dispense: i suoi 5 punti, t = 0 … 4, p = 2, la derivata iniziale e i nodi 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.row.point": "C({t}) = p{i}",
  "bsplineInterpolation.row.start": "C′({t}) = D₀",
  "bsplineInterpolation.row.end": "C′({t}) = D{i}",
  "bsplineInterpolation.col.condition": "Condizione",
  "bsplineInterpolation.col.unknown": "Incognita",
  "bsplineInterpolation.col.rhs": "Termine noto",
  "bsplineInterpolation.col.solution": "Soluzione",
  "bsplineInterpolation.tableCaption":
    "Il sistema A r = b da bsplineInterpolationSystem ({size} × {size}): la riga i è una condizione, la colonna j il peso di rⱼ in essa (Nⱼ,ₚ(tᵢ) o N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableCaptionNotes":
    "Il sistema {size} × {size} delle dispense A r = b (bsplineInterpolationSystem): la riga i è una condizione, la colonna j il peso di rⱼ in essa (Nⱼ,ₚ(tᵢ) o N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableTooLarge":
    "Il sistema ha {size} incognite; la tabella mostra sistemi fino a {max}. Rimuovi punti o diminuisci il grado per vederlo.",
  "bsplineInterpolation.whatYouSee":
    "La curva passa per i punti dati pᵢ (le maniglie rotonde) nei parametri tᵢ; è una B-spline i cui punti di controllo rⱼ (i quadrati grigi e il poligono tratteggiato) non sono assegnati ma calcolati: ogni punto dato, e ogni derivata all'estremo Dᵢ (le frecce, a lunghezza intera, derivata rispetto a t), è un'equazione lineare nelle rⱼ, e la tabella sotto la figura è quel sistema quadrato con la sua soluzione. La figura iniziale è l'esempio svolto delle dispense croate (sezione 5 del programma): cinque punti in t = 0 … 4, una quadratica, una derivata iniziale e i nodi 0 0 0 1 2 3 4 4 4, che danno il sistema 6 × 6 con righe 1; −2 2; ½ ½ … .",
  "bsplineInterpolation.try1":
    "Nell'esempio, leggi la seconda riga: −2 r₀ + 2 r₁ = D₀, quindi r₁ = p₀ + D₀/2 — il quadrato grigio r₁ sta a metà della freccia. Trascina la punta della freccia e osserva r₁ seguirla.",
  "bsplineInterpolation.try2":
    "Aumenta il grado passo dopo passo: la curva passa ancora per ogni punto, ma le righe si allungano (ogni condizione coinvolge p + 1 punti di controllo) e il poligono di controllo si allarga sempre di più.",
  "bsplineInterpolation.try3":
    "Trascina p₂ molto a destra: con parametri uniformi la curva oscilla ben oltre p₂ e p₃. Passa alla lunghezza di corda: ora i tᵢ crescono con i lati e l'oscillazione si riduce — ma D₀, una derivata rispetto a t, è ora troppo veloce per un parametro che misura la lunghezza: accorcia la freccia e l'uncino in p₀ scompare.",
  "interpolateApproximate.title": "Interpolare o approssimare",
  "interpolateApproximate.summary":
    "Gli stessi punti come punti di controllo (la curva ne è attratta), come dati raggiunti esattamente, o come dati approssimati da meno punti di controllo nel senso dei minimi quadrati.",
  "interpolateApproximate.aria.control":
    "B-spline {kind} con i {count} punti come punti di controllo (nodi vincolati): passa solo per il primo e l'ultimo",
  "interpolateApproximate.aria.data":
    "B-spline {kind} approssimante {count} punti dati con {control} ({fit}); residuo massimo {max}",
  "interpolateApproximate.aria.interpolation": "interpolazione",
  "interpolateApproximate.aria.leastSquares": "minimi quadrati, estremi esatti",
  "interpolateApproximate.roleLegend": "I punti sono",
  "interpolateApproximate.role.control": "punti di controllo (approssimazione)",
  "interpolateApproximate.role.data": "punti dati (interpolazione o minimi quadrati)",
  "interpolateApproximate.degreeLegend": "Grado p",
  "interpolateApproximate.degreeOption": "{p}",
  "interpolateApproximate.minPoints": "una B-spline di grado {degree} richiede almeno {min} punti",
  "interpolateApproximate.maxPoints": "questa demo consente al massimo {max} punti",
  "interpolateApproximate.control.count": "Punti di controllo (tutti = interpolazione)",
  "interpolateApproximate.control.count.input": "numero di punti di controllo",
  "interpolateApproximate.countRange":
    "il numero di punti di controllo deve essere un intero da {min} (grado + 1) a {max} (i punti), ricevuto “{value}”",
  "interpolateApproximate.controlPoints.many": "{count} punti di controllo",
  "interpolateApproximate.controlPoints.one": "{count} punto di controllo",
  "interpolateApproximate.controlPoints.other": "{count} punti di controllo",
  "interpolateApproximate.note.control":
    "I punti sono il poligono di controllo: la curva parte da P₀, finisce in Pₙ e si avvicina soltanto agli altri.",
  "interpolateApproximate.note.interpolation":
    "Interpolazione: un punto di controllo per punto dato, la curva raggiunge ogni pₖ (residuo massimo {max}).",
  "interpolateApproximate.note.leastSquares":
    "Minimi quadrati, estremi esatti: Σ |pₖ − C(tₖ)|² = {sum}; residuo massimo {max} (in p{k}).",
  "interpolateApproximate.legendCurve": "la B-spline C(u)",
  "interpolateApproximate.legendGiven": "poligono di controllo: i punti",
  "interpolateApproximate.legendFitted": "poligono di controllo rⱼ (calcolato)",
  "interpolateApproximate.legendResidual": "residuo pₖ − C(tₖ)",
  "interpolateApproximate.tex.control": "nodi uniformi vincolati",
  "interpolateApproximate.whatYouSee":
    "Gli stessi punti possono avere due ruoli. Come punti di controllo modellano una B-spline che parte dal primo, finisce nell'ultimo e si avvicina soltanto agli altri — l'approssimazione del design interattivo delle dispense. Come punti dati (con parametri tₖ a lunghezza di corda) sono raggiunti esattamente da una B-spline interpolante con altrettanti punti di controllo, oppure, con meno punti di controllo, approssimati nel senso dei minimi quadrati con entrambi gli estremi esatti: i brevi segmenti da ogni punto alla curva sono i residui pₖ − C(tₖ), e i quadrati grigi sul poligono tratteggiato i punti di controllo calcolati. Sezione 5 del programma (interpolazione e approssimazione), dalle dispense croate e greche.",
  "interpolateApproximate.try1":
    "Alterna punti di controllo e punti dati: come punti di controllo la curva taglia all'interno di ogni picco e tocca solo P₀ e P₉; come dati passa vicino a ogni punto, e con il numero a 10 per ciascuno di essi.",
  "interpolateApproximate.try2":
    "Come dati, porta il numero di punti di controllo da 10 fino a 4: la curva si distende, i segmenti dei residui crescono e la somma dei quadrati sale da 0 a circa 78 — non a ogni singolo passo (ogni numero ha nodi propri), ma il primo e l'ultimo punto restano sempre esatti.",
  "interpolateApproximate.try3":
    "Imposta il numero a 10 (interpolazione) e trascina p₄ bruscamente verso il basso: l'intera curva si increspa per passarci. Porta il numero a 5 e trascina di nuovo: la curva approssimante si inclina soltanto verso il punto, e invece cresce il suo residuo.",
  "app.language": "Lingua",
  "section.7": "7 · Progettazione interattiva",
  "gallery.lecture": "Lezione: questa sezione scena per scena, da proiettare",
  "gallery.exercise": "Esercizio: {title}",
  "exercise.label": "Esercizio",
  "exercise.check": "Verifica",
  "exercise.hint": "Suggerimento",
  "exercise.solved": "Risolto: il nucleo di calcolo lo conferma.",
  "exercise.unknown": "Non esiste un esercizio “{id}”.",
  "exercise.close-the-gap.title": "Colma la distanza",
  "exercise.close-the-gap.task":
    "Le due cubiche non si incontrano. Trascina Q₀ su P₃ in modo che la curva sia continua (C⁰).",
  "exercise.close-the-gap.hint":
    "C⁰ chiede solo che l'ultimo punto del primo pezzo sia il primo punto del secondo: Q₀ = P₃ = (4; 1).",
  "exercise.close-the-gap.notYet": "Non ancora: Q₀ dista {detail} da P₃.",
  "exercise.make-it-c1.title": "Rendi C¹ la giunzione",
  "exercise.make-it-c1.task":
    "I pezzi si incontrano, ma formano un angolo. Sposta Q₁ in modo che la giunzione sia C¹: la stessa derivata da entrambi i lati.",
  "exercise.make-it-c1.hint":
    "Per due cubiche C¹ significa 3(P₃ − P₂) = 3(Q₁ − Q₀), quindi Q₁ = 2P₃ − P₂ = (5; −1).",
  "exercise.make-it-c1.notYet":
    "Non ancora: il nucleo di calcolo misura C{detail} nella giunzione.",
  "exercise.bezier-pieces.title": "Taglia la curva in segmenti di Bézier",
  "exercise.bezier-pieces.task":
    "Inserisci nodi finché ogni nodo interno ha molteplicità p = 2: allora la curva si scompone in segmenti di Bézier quadratici.",
  "exercise.bezier-pieces.hint":
    "I nodi interni sono 1, 2 e 3, ciascuno una volta. Inseriscili ancora una volta ciascuno: imposta u al valore del nodo e premi “Inserisci”.",
  "exercise.bezier-pieces.notYet":
    "Non ancora: nodi interni in cui la curva è ancora C¹: {detail}.",
  "exercise.quarter-circle.title": "Un quarto di circonferenza",
  "exercise.quarter-circle.task":
    "I punti di controllo (4; 0), (4; 4), (0; 4) formano un triangolo isoscele. Scegli il peso w₁ in modo che l'arco sia esattamente un quarto della circonferenza di raggio 4 centrata in (0; 0).",
  "exercise.quarter-circle.hint":
    "Per un arco di circonferenza w₁ è il coseno di metà dell'angolo al centro: qui l'angolo è di 90°, quindi w₁ = cos 45° = √2/2 ≈ 0,7071.",
  "exercise.quarter-circle.notYet": "Non ancora: il raggio varia del {detail} % lungo l'arco.",
  "exercise.natural-ends.title": "Una spline naturale",
  "exercise.natural-ends.task":
    "Questa spline usa la condizione agli estremi not-a-knot. Cambiala in modo che la spline sia naturale: nessuna flessione agli estremi.",
  "exercise.natural-ends.hint":
    "Naturale significa C″ = 0 a entrambi gli estremi: scegli la condizione agli estremi “naturale”.",
  "exercise.natural-ends.notYet": "Non ancora: |C″| agli estremi vale {detail}.",
  "exercise.horn-torus.title": "Un toro a corno",
  "exercise.horn-torus.task":
    "Modifica il toro in modo che il suo tubo tocchi l'asse di rotazione: un toro a corno.",
  "exercise.horn-torus.hint":
    "La circonferenza del tubo ha centro in (R, 0, 0) e raggio r; tocca l'asse z quando R = r.",
  "exercise.horn-torus.notYet": "Non ancora: il tubo resta a {detail} dall'asse.",
  "exercise.through-every-point.title": "Attraverso tutti i punti",
  "exercise.through-every-point.task":
    "La curva tocca solo il primo e l'ultimo punto. Senza spostare alcun punto, falla passare per tutti.",
  "exercise.through-every-point.hint":
    "Usa i punti come punti dati invece che come punti di controllo, con tanti punti di controllo quanti sono i punti dati: interpolazione invece di approssimazione.",
  "exercise.through-every-point.notYet": "Non ancora: la curva passa per {detail} dei punti.",
  "lecture.label": "Lezione",
  "lecture.previous": "← Precedente",
  "lecture.next": "Successiva →",
  "lecture.counter": "{k} / {n}",
  "lecture.unknown": "Non esiste una lezione “{id}”.",
  "lecture.loadFailed": "Impossibile caricare la lezione “{id}” (HTTP {status}).",

  // ---- The curve library's errors by code (lib/core-errors.js; English: lib/strings/core-errors.js) ----
  "coreError.number.nan": "NaN",
  "coreError.number.infinity": "∞",
  "coreError.number.negativeInfinity": "−∞",
  "coreError.indexed": "{subject} {index}",
  "coreError.spacing.uniform": "uniforme",
  "coreError.spacing.chord": "a lunghezza di corda",
  "coreError.spacing.centripetal": "centripeta",
  "coreError.spacing.alpha": "alpha = {alpha}",
  "coreError.end.first": "primi",
  "coreError.end.last": "ultimi",
  "coreError.bufferLength": "lunghezza {length}",
  "coreError.invalid-dimension": "dim deve essere 2 o 3, ricevuto {dim}",
  "coreError.coordinate-count":
    "il numero di coordinate {count} non è multiplo di dim = {dim}; i punti si danno in forma piatta [{firstPoint}, x1, …]",
  "coreError.not-finite":
    "{subject}: il valore {value} non è ammesso; ogni numero deve essere finito",
  "coreError.coordinate-too-large":
    "{subject}: il valore {value} è troppo grande; una coordinata deve avere valore assoluto al più {max}, perché derivate e lunghezze restino finite",
  "coreError.too-few-points.one":
    "{what}: serve almeno {needed} punto di controllo, ricevuti {got}",
  "coreError.too-few-points.many":
    "{what}: servono almeno {needed} punti di controllo, ricevuti {got}",
  "coreError.too-few-points.other":
    "{what}: servono almeno {needed} punti di controllo, ricevuti {got}",
  "coreError.weight-count":
    "i pesi devono avere un valore per punto di controllo ({expected}), ricevuti {got}",
  "coreError.non-positive-weight":
    "il peso {index} vale {value}; i pesi devono essere > 0 (pesi nulli o negativi possono creare poli sulla curva)",
  "coreError.parameter-out-of-range": "{name} = {value} è fuori dal dominio [{min}; {max}]",
  "coreError.index-out-of-range":
    "l'indice di punto di controllo {index} è fuori intervallo: la curva ha {count} punti (0..={last})",
  "coreError.point-dimension": "un punto richiede {expected} coordinate, ricevute {got}",
  "coreError.invalid-tolerance":
    "la tolleranza {value} non è utilizzabile: deve essere un numero finito > 0",
  "coreError.tolerance-too-small":
    "la tolleranza {value} non è utilizzabile: è sotto {relative} × la dimensione della curva ({size}); dominerebbero gli errori di arrotondamento",
  "coreError.flattening-stalled":
    "la tolleranza {value} non è utilizzabile: nessun pezzo della curva è abbastanza piatto a questa precisione",
  "coreError.invalid-interval": "l'intervallo [{a}; {b}] è vuoto; serve a < b",
  "coreError.unknown-option": "{name} deve essere uno tra {expected}, ricevuto “{value}”",
  "coreError.in-argument": "{argument}: {message}",
  "coreError.knot-count":
    "il vettore dei nodi deve avere n+p+2 = {n} + {degree} + 2 = {expected} valori, ricevuti {got}",
  "coreError.knot-order":
    "i nodi non devono decrescere: u_{index} = {value} viene dopo u_{previousIndex} = {previous}",
  "coreError.empty-domain":
    "il dominio [u_p, u_(n+1)] = [u_{degree}, u_{points}] = [{a}; {b}] è vuoto; serve u_{degree} < u_{points}",
  "coreError.knot-multiplicity":
    "il nodo {knot} compare {multiplicity} volte (u_{first}..u_{last}); una curva di grado {degree} ammette al massimo p+1 = {order}",
  "coreError.insertion-multiplicity.one":
    "inserire il nodo {knotValue} {times} volta gli darebbe molteplicità {multiplicity}; il grado {degree} ammette al massimo p+1 = {order}",
  "coreError.insertion-multiplicity.many":
    "inserire il nodo {knotValue} {times} volte gli darebbe molteplicità {multiplicity}; il grado {degree} ammette al massimo p+1 = {order}",
  "coreError.insertion-multiplicity.other":
    "inserire il nodo {knotValue} {times} volte gli darebbe molteplicità {multiplicity}; il grado {degree} ammette al massimo p+1 = {order}",
  "coreError.degree-zero": "il grado deve essere almeno 1, ricevuto 0",
  "coreError.degree-out-of-range": "il grado deve essere 1..={max}, ricevuto {degree}",
  "coreError.too-few-points-for-degree":
    "il grado {degree} richiede almeno p+1 = {order} punti di controllo, ricevuti {got}",
  "coreError.coincident-points":
    "i punti {index} e {next} coincidono; la parametrizzazione {kind} richiede punti consecutivi distinti",
  "coreError.phantom-even-degree":
    "i punti fantasma fanno passare una B-spline uniforme di grado dispari per i suoi estremi; il grado {degree} è pari",
  "coreError.not-a-span":
    "l'intervallo {span} non è un intervallo non vuoto del dominio (validi: [{valid}])",
  "coreError.rational-join":
    "le regole di giunzione valgono per pezzi di Bézier polinomiali; questi hanno pesi",
  "coreError.join-degree.one":
    "la regola {rule} fissa {needed} punto del pezzo destro; i gradi {left} e {right} sono troppo bassi (ogni pezzo richiede grado >= {needed})",
  "coreError.join-degree.many":
    "la regola {rule} fissa {needed} punti del pezzo destro; i gradi {left} e {right} sono troppo bassi (ogni pezzo richiede grado >= {needed})",
  "coreError.join-degree.other":
    "la regola {rule} fissa {needed} punti del pezzo destro; i gradi {left} e {right} sono troppo bassi (ogni pezzo richiede grado >= {needed})",
  "coreError.no-joint-tangent":
    "G1 richiede una tangente nella giunzione, ma gli ultimi due punti del pezzo sinistro coincidono",
  "coreError.breakpoint-count":
    "pezzi: {pieces}; servono {breakpoints} punti di raccordo, ricevuti {got}",
  "coreError.degenerate-line": "la retta richiede due punti diversi, ricevuto due volte ({x}; {y})",
  "coreError.curve-batch-length":
    "{count} coordinate non si dividono in curve di grado {degree} ((degree + 1)·dim = {perCurve} numeri ciascuna)",
  "coreError.rational-hodograph":
    "l'odografo di una curva razionale non è una curva di Bézier di grado n − 1; campiona invece derivative(t, 1)",
  "coreError.mapped-weight":
    "la trasformazione porta il punto di controllo {index} al peso {weight}; i pesi devono restare > 0 (il punto attraverserebbe la retta all'infinito)",
  "coreError.singular-map": "la trasformazione proiettiva è singolare (determinante 0)",
  "coreError.matrix-size":
    "una trasformazione proiettiva è una matrice 3×3 (9 numeri, riga per riga), ricevuti {got}",
  "coreError.degenerate-triangle":
    "un arco di circonferenza richiede un vero triangolo P0 P1 P2 (nessun punto coincidente o allineato)",
  "coreError.not-isosceles":
    "un arco di circonferenza richiede un triangolo isoscele: |P0P1| = {first} ma |P1P2| = {second}",
  "coreError.arc-point-count":
    "un arco di circonferenza richiede 3 punti di controllo (6 numeri), ricevuti {got}",
  "coreError.invalid-sweep":
    "l'ampiezza deve essere non nulla e al massimo un giro completo (2π), ricevuto {sweep}",
  "coreError.parallel-axes": "i due assi di un'ellisse non devono essere paralleli né nulli",
  "coreError.axis-lengths":
    "center, axisX e axisY devono avere la stessa lunghezza, ricevuti {center}, {axisX}, {axisY}",
  "coreError.not-positive": "{name}: deve essere > 0, ricevuto {value}",
  "coreError.dimension-mismatch":
    "entrambi i pezzi devono avere la stessa dim, ricevuti {left} e {right}",
  "coreError.piece-point-count":
    "i gradi [{degrees}] richiedono in tutto {needed} punti di controllo (n + 1 per pezzo), ricevuti {got}",
  "coreError.buffer-length":
    "il buffer di uscita ha {len} valori, {count} punti ne richiedono {needed}",
  "coreError.net-coordinate-count":
    "i punti devono contenere rows·cols·3 = {rows}·{cols}·3 = {total} coordinate, ricevute {got}",
  "coreError.patch-too-small":
    "una patch di Bézier richiede almeno 2 righe e 2 colonne (grado ≥ 1 in ogni direzione), ricevuto {rows} × {cols}",
  "coreError.net-index-out-of-range":
    "il punto di controllo (i, j) = ({i}; {j}) è fuori intervallo: la rete ha {rows} × {cols} punti (i in 0..={lastI}, j in 0..={lastJ})",
  "coreError.no-normal":
    "la superficie non ha normale in (u, v) = ({u}; {v}): lì ∂S/∂u × ∂S/∂v = 0, anche nel limite dall'interno del dominio",
  "coreError.empty-tessellation":
    "tessellate richiede almeno 1 quadrilatero in ogni direzione, ricevuti nu = {nu}, nv = {nv}",
  "coreError.too-large": "{what} = {value}: troppo; è ammesso al massimo {max}",
  "coreError.result-too-large":
    "{what} = {counts} valori da {valueBytes} byte = {bytes} byte: troppo; un risultato può occupare al massimo {maxBytes} byte ({mib} MiB)",
  "coreError.argument-type": "{name} deve essere {expected}, ricevuto {got}",
  "coreError.not-whole-number":
    "{subject}: deve essere un numero intero da 0 a {max}, ricevuto {value}",
  "coreError.needs-2d": "{operation} funziona su curve 2D; questa curva ha dim = {dim}",
  "coreError.needs-3d":
    "{operation} costruisce una superficie 3D e richiede una curva 3D; questa curva ha dim = {dim}",
  "coreError.zero-direction": "{name} non deve essere il vettore nullo (non dà una direzione)",
  "coreError.needs-polynomial":
    "{operation} funziona su patch polinomiali; questa ha pesi (una patch razionale ha un denominatore)",
  "coreError.all-weights-zero":
    "tutti i {count} pesi sono 0: il denominatore w(t) = Σ w_i B_i(t) è 0 per ogni t, quindi non c'è alcuna curva",
  "coreError.param-count": "params deve avere un valore per punto ({points}), ricevuti {params}",
  "coreError.params-not-increasing":
    "params deve crescere strettamente: t_{index} = {value} non è maggiore di t_{previousIndex} = {previous}",
  "coreError.missing-argument": "{neededBy}: serve {name}, che non è stato dato",
  "coreError.argument-length": "{name} deve avere {expected} numeri, ricevuti {got}",
  "coreError.not-closed":
    "l'interpolazione periodica richiede che l'ultimo punto (punto {last}) sia uguale al primo",
  "coreError.alpha-out-of-range":
    "alpha = {value} è fuori da [0; 1] (0 uniforme; 0,5 centripeta; 1 corda)",
  "coreError.control-count-out-of-range":
    "count = {count} punti di controllo è fuori da [grado + 1, numero di punti] = [{min}; {max}]",
  "coreError.schoenberg-whitney":
    "il sistema di interpolazione è singolare: t_{index} = {param} deve stare nel supporto (u_{index}, u_{hiIndex}) = ({lo}; {hi}) di N_{index},{degree} (condizione di Schoenberg–Whitney)",
  "coreError.too-few-data-points.one": "{what}: serve almeno {needed} punto dato, ricevuti {got}",
  "coreError.too-few-data-points.many":
    "{what}: servono almeno {needed} punti dati, ricevuti {got}",
  "coreError.too-few-data-points.other":
    "{what}: servono almeno {needed} punti dati, ricevuti {got}",
  "coreError.stroke-far-from-curve":
    "il tratto inizia a distanza {startDistance} e finisce a distanza {endDistance} dalla curva; per ridisegnarne una parte, inizia e termina il tratto entro {near} dalla curva (una curva aperta si prolunga anche con un tratto che inizia o finisce su di essa)",
  "coreError.singular-system":
    "{what}: il sistema è singolare; l'eliminazione ha incontrato un pivot nullo nella riga {row}",
  "coreError.spline-kind":
    "{operation} funziona su spline costruite con {needs}; questa è stata costruita con {got}",
  "coreError.conflicting-options": "{first} non si può combinare con {second}: {reason}",
  "coreError.knots-not-clamped":
    "un'approssimazione ai minimi quadrati con estremi esatti richiede nodi vincolati agli estremi (clamped): i {end} p+1 = {order} nodi devono essere uguali a {param}",
  "coreError.freed": "questo {className} è stato liberato (free)",
  "coreError.no-constructor":
    "new {className}() non è disponibile: un {className} si ottiene da {makers}",
  "coreError.out-buffer":
    "out deve essere un Float64Array o number[] di almeno dim = {dim} numeri, ricevuto {got}",
  "coreError.internal": "errore interno della libreria di curve: {message}",
  "coreError.place.pieceField": "pieces[{piece}].{field}",
  "coreError.place.piece": "pieces[{piece}]",
  "coreError.place.field": "{field}",
  "coreError.place.none": "espressione",
  "coreError.place.range": "{place}, caratteri {start}–{end}",
  "coreError.place.at": "{place}: {message}",
  "coreError.expression-empty": "non è scritto nulla; scrivete un'espressione in t, come cos(t)",
  "coreError.expression-too-long":
    "l'espressione ha {length} caratteri; ne sono ammessi al massimo {max}",
  "coreError.expression-too-deep":
    "parentesi, potenze e funzioni sono annidate più di {max} livelli",
  "coreError.expression-too-large": "l'espressione ha più di {max} numeri, nomi e operazioni",
  "coreError.unexpected-character":
    "“{character}” non fa parte del linguaggio; usate numeri, t, + − * / ^ e parentesi",
  "coreError.unexpected-character.comma": "“,” non si usa: scrivete i decimali con il punto (2.5)",
  "coreError.unexpected-character.bar": "“|” non si usa: scrivete abs(t)",
  "coreError.expected-operand": "prima di “{found}” serve un numero, un nome o “(”",
  "coreError.expected-operand.end": "l'espressione finisce dove serve un numero, un nome o “(”",
  "coreError.missing-operator": "manca un operatore prima di “{found}” (scrivete * o + fra i due)",
  "coreError.unclosed-parenthesis": "questa “(” non viene mai chiusa; aggiungete “)”",
  "coreError.unmatched-parenthesis": "questa “)” non ha una “(” prima di sé",
  "coreError.unknown-name":
    "nome sconosciuto “{name}”; usate t, pi, e, una funzione come sin(t) o un parametro",
  "coreError.function-needs-parentheses": "{name} vuole le parentesi: scrivete {name}(t)",
  "coreError.function-power":
    "{name}^ vuole un intero ≥ 1 prima delle parentesi: {name}^2(t) significa ({name}(t))^2",
  "coreError.function-power.trig":
    "{name}^ vuole un intero ≥ 1 (sin^2(t)); la funzione inversa è a{name}(t)",
  "coreError.ambiguous-division": "“{text}” è ambiguo: scrivete {product} oppure {quotient}",
  "coreError.number-after-name":
    "un numero dopo un nome: scrivete {number}{name} oppure {name}^{number}",
  "coreError.scientific-notation":
    "“{text}” non è letto come potenza di dieci (e è il numero di Eulero): scrivete il decimale, come 0.001, o un prodotto, come 2.5*10^3",
  "coreError.invalid-number": "“{text}” non è un numero",
  "coreError.invalid-parameter-name":
    "“{name}” non può essere un parametro: usate una lettera diversa da t ed e (a, b, ω) o una lettera con pedice (a_1)",
  "coreError.unknown-parameter": "la curva non ha il parametro “{name}”",
  "coreError.not-finite-value": "il valore è {value}; deve essere un numero finito",
  "coreError.empty-piece-interval": "l'intervallo [{from}; {to}] è vuoto; serve from < to",
  "coreError.pieces-do-not-join":
    "inizia in {from} ma il pezzo precedente finisce in {previous}; i pezzi si raccordano in t",
  "coreError.missing-field":
    "questo campo manca; ogni pezzo vuole x, y, from e to (e z su tutti i pezzi o su nessuno)",
  "coreError.piece-count": "una curva vuole da 1 a {max} pezzi, ricevuti {count}",
  "coreError.not-polynomial":
    "questo pezzo non è un polinomio in t, quindi non ha una forma di Bézier",
  "coreError.bound-uses-t":
    "un estremo è un numero e non può dipendere da t; scrivetelo con numeri, pi, e e parametri",
  "coreError.subject.adaptive-depth":
    "profondità della suddivisione adattiva (la tolleranza è vicina all'arrotondamento)",
  "coreError.subject.adaptive-vertices": "vertici della mesh adattiva",
  "coreError.subject.adaptive-vertices-leaves":
    "vertici della mesh adattiva (almeno uno per foglia)",
  "coreError.subject.adaptive-vertices-patches":
    "vertici della mesh adattiva (almeno uno per patch di Bézier)",
  "coreError.subject.basis-sample-count":
    "count (campioni per funzione di base: un valore per funzione ciascuno)",
  "coreError.subject.bessel-spline": "una spline di Bessel",
  "coreError.subject.bezier-curve": "una curva di Bézier",
  "coreError.subject.boolean": "un booleano",
  "coreError.subject.bspline-interpolation-system": "il sistema di interpolazione B-spline",
  "coreError.subject.cardinal-spline": "una spline cardinale",
  "coreError.subject.catmull-rom-spline": "una spline di Catmull–Rom",
  "coreError.subject.clamped-end-condition": "la condizione agli estremi vincolata (clamped)",
  "coreError.subject.closed-has-no-ends": "una curva chiusa non ha estremi",
  "coreError.subject.closed-interpolating-bspline":
    "una B-spline interpolante chiusa di questo grado (p + 1, almeno 3)",
  "coreError.subject.closed-knots-computed":
    "i nodi di una curva chiusa sono quelli periodici calcolati dai params",
  "coreError.subject.composite-curve": "una curva composta (pezzi)",
  "coreError.subject.coordinate": "coordinata",
  "coreError.subject.cubic-spline": "una spline cubica",
  "coreError.subject.cubic-spline-system": "il sistema delle tangenti della spline cubica",
  "coreError.subject.curvature-work": "punti di curvatura per questo grado (budget di lavoro 2^28)",
  "coreError.subject.curve": "una BSplineCurve o BezierCurve",
  "coreError.subject.data-point-count": "numero di punti dati",
  "coreError.subject.degree-u-rows": "degreeU (righe lungo u)",
  "coreError.subject.degree-v-columns": "degreeV (colonne lungo v)",
  "coreError.subject.derivative-order": "ordine di derivazione",
  "coreError.subject.every-piece": "ogni pezzo (grado >= 1)",
  "coreError.subject.flattening-segments": "numero di segmenti della linearizzazione",
  "coreError.subject.flattening-segments-estimated":
    "numero di segmenti della linearizzazione (stimato prima di linearizzare: abbassa il grado o aumenta la tolleranza)",
  "coreError.subject.grid-points": "punti della griglia us.length·vs.length",
  "coreError.subject.hermite-spline": "una spline di Hermite",
  "coreError.subject.interpolating-bspline":
    "una B-spline interpolante di questo grado (p + 1 − derivate agli estremi, almeno 2)",
  "coreError.subject.interpolating-surface":
    "una superficie interpolante di questo grado (grado + 1 per direzione)",
  "coreError.subject.interpolation-system-size":
    "la dimensione del sistema di interpolazione (incognite)",
  "coreError.subject.knot": "nodo",
  "coreError.subject.knot-to-insert": "nodo da inserire",
  "coreError.subject.lagrange-curve": "una curva di Lagrange",
  "coreError.subject.lagrange-point-count": "numero di punti di una curva di Lagrange",
  "coreError.subject.least-squares-bspline":
    "una B-spline ai minimi quadrati di questo grado (p + 1, almeno 2)",
  "coreError.subject.least-squares-system": "le equazioni normali dei minimi quadrati",
  "coreError.subject.length": "la sua lunghezza",
  "coreError.subject.matrix-entry": "elemento della matrice",
  "coreError.subject.new-point-coordinate": "la coordinata del nuovo punto",
  "coreError.subject.numbers": "un array di numeri (Float64Array o number[])",
  "coreError.subject.object": "un oggetto",
  "coreError.subject.parameter": "parametro",
  "coreError.subject.parametrisation": "una parametrizzazione",
  "coreError.subject.phantom-points": "punti fantasma di questo grado",
  "coreError.subject.polynomial": "un polinomio",
  "coreError.subject.rational-bezier-curve": "una curva di Bézier razionale",
  "coreError.subject.rational-derivative-order": "ordine di derivazione di una curva razionale",
  "coreError.subject.refine-result":
    "refine: (punti di controllo + us.length) × coordinate omogenee",
  "coreError.subject.sample-count": "numero di campioni",
  "coreError.subject.sample-work": "numero di campioni per questo grado (budget di lavoro 2^28)",
  "coreError.subject.sample-derivatives-result": "sampleDerivatives: us.length × coordinate",
  "coreError.subject.sample-grid-result": "sampleGrid: us.length × vs.length × 3 coordinate",
  "coreError.subject.sample-params-result": "sample: params.length × coordinate",
  "coreError.subject.sample-ts-result": "sample: ts.length × coordinate",
  "coreError.subject.sample-uniform-result": "sampleUniform: count × coordinate",
  "coreError.subject.sample-uniform-view-result": "sampleUniformView: count × coordinate",
  "coreError.subject.sample-view-result": "sampleView: params.length × coordinate",
  "coreError.subject.samples-result": "campioni (punti × coordinate)",
  "coreError.subject.start-angle": "angolo iniziale",
  "coreError.subject.string": "una stringa",
  "coreError.subject.stroke": "un tratto",
  "coreError.subject.surface-derivative-order": "ordine di derivazione du + dv",
  "coreError.subject.tessellation-vertices": "vertici della tassellazione (nu + 1)(nv + 1)",
  "coreError.subject.tessellation-work":
    "vertici della tassellazione (nu + 1)(nv + 1) per questo grado (budget di lavoro 2^28)",
  "coreError.subject.weight": "peso",
  // The typed piecewise curve (section 1, www/demos/piecewise.js) and its exercise.
  "piecewise.title": "Curve a pezzi e le loro giunzioni",
  "piecewise.summary":
    "Scrivi x(t), y(t) e l'intervallo di ogni pezzo; il nucleo di calcolo classifica ogni giunzione come Cᵏ o Gᵏ, lo dimostra dove può e mostra affiancati i valori unilaterali.",
  "piecewise.aria": "Una curva di {count} pezzi scritti come formule; giunzioni: {joints}",
  "piecewise.ariaNoJoints": "Una curva di un solo pezzo scritto come formula: nessuna giunzione",
  "piecewise.whatYouSee":
    "Ogni pezzo Pᵢ(t) = (x(t), y(t)) è disegnato nel suo colore sul suo intervallo; dove un intervallo finisce comincia il successivo (sezione 1 del programma: pezzi su [0, 1) e [1, 2]). In ogni giunzione le frecce sono le velocità in arrivo, P′(t⁻), e in partenza, P′(t⁺); la tabella sotto la figura elenca i valori unilaterali x(t⁻), x(t⁺), x′(t⁻), x′(t⁺), … e il primo ordine di derivata in cui differiscono. Il verdetto Cᵏ (continuità parametrica: le derivate fino all'ordine k coincidono) o Gᵏ (continuità geometrica: solo la forma, cioè la direzione, poi la curvatura) è del nucleo di calcolo, dimostrato in aritmetica esatta per i pezzi polinomiali.",
  "piecewise.try1":
    "Premi “C⁰, non C¹”: x′(1⁻) = −2 ma x′(1⁺) = 0, quindi la velocità salta e la curva ha uno spigolo. Poi premi “C¹”: x′ coincide, salta solo x″.",
  "piecewise.try2":
    "Nel pezzo 2 scrivi tu x(t) = t^2 - 4t + 3, poi cambia 3 in 4: la giunzione si rompe (non C⁰) e la figura mostra lo scarto.",
  "piecewise.try3":
    "Premi “G¹, non C¹”: il secondo pezzo è la stessa parabola percorsa a velocità doppia, quindi la forma è liscia (G¹ e oltre) anche se P′ raddoppia in t = 1.",
  "piecewise.pieces": "Pezzi",
  "piecewise.piece": "Pezzo {i}",
  "piecewise.field.x": "x(t) =",
  "piecewise.field.y": "y(t) =",
  "piecewise.field.from": "da t =",
  "piecewise.field.to": "a t =",
  "piecewise.field.name": "{field} del pezzo {i}",
  "piecewise.fieldName.x": "x(t)",
  "piecewise.fieldName.y": "y(t)",
  "piecewise.fieldName.from": "inizio dell'intervallo",
  "piecewise.fieldName.to": "fine dell'intervallo",
  "piecewise.addPiece": "Aggiungi un pezzo",
  "piecewise.addPiece.title": "Aggiungi un pezzo dopo l'ultimo, a partire da dove finisce",
  "piecewise.removePiece": "Rimuovi l'ultimo pezzo",
  "piecewise.removePiece.title": "Rimuovi l'ultimo pezzo (ne resta almeno uno)",
  "piecewise.maxPieces": "questa demo consente al massimo {max} pezzi",
  "piecewise.minPieces": "una curva richiede almeno un pezzo",
  "piecewise.typingError": "Pezzo {i}, {field}: {message}",
  "piecewise.presets": "L'esercizio delle dispense e altro",
  "piecewise.preset.title": "Sostituisci i pezzi con questo esempio",
  "piecewise.preset.notC0": "Non C⁰",
  "piecewise.preset.c1": "C¹",
  "piecewise.preset.c0": "C⁰, non C¹",
  "piecewise.preset.g1": "G¹, non C¹",
  "piecewise.jointsLegend": "Giunzioni",
  "piecewise.noJoints": "Un solo pezzo: nessuna giunzione da verificare.",
  "piecewise.joint": "t = {t}: {verdict}",
  "piecewise.verdict": "{c}, {g}",
  "piecewise.verdict.broken": "non C⁰: i pezzi non si incontrano",
  "piecewise.verdict.infinite": "C∞: entrambi i lati sono un unico polinomio",
  "piecewise.proven": "dimostrato (aritmetica esatta)",
  "piecewise.measured": "misurato (virgola mobile)",
  "piecewise.breakProven":
    "misurato (virgola mobile); che l'ordine {order} differisca è dimostrato (aritmetica degli intervalli)",
  "piecewise.figureVerdict": "t = {t}: {verdict} ({how})",
  "piecewise.tag": "t = {t}",
  "piecewise.leftArrow": "P′({t}⁻)",
  "piecewise.rightArrow": "P′({t}⁺)",
  "piecewise.incomplete":
    "Una parte della curva non è stata raffinata entro il budget di calcolo; lì è disegnata in modo più grossolano.",
  "piecewise.tableCaption": "Giunzione in t = {t}: {verdict}, {how}",
  "piecewise.col.quantity": "Valore",
  "piecewise.col.left": "da sinistra (t⁻)",
  "piecewise.col.right": "da destra (t⁺)",
  "piecewise.col.agree": "Coincidono?",
  "piecewise.agree.yes": "sì",
  "piecewise.agree.no": "no",
  "piecewise.undefined": "non definito",
  "piecewise.formula.joint": "giunzione in",
  "piecewise.formula.proven": "dimostrato",
  "piecewise.formula.measured": "misurato",
  "piecewise.formula.breakProven": "misurato; l'ordine {order} differisce: dimostrato",
  "piecewise.formula.notC0": "non C⁰",
  "piecewise.badPiece":
    "campo “{field}”: il pezzo {index} deve essere [x, y, from, to] con testi di al massimo 1000 caratteri",
  "exercise.piecewise-c1.title": "Scrivi un secondo pezzo C¹",
  "exercise.piecewise-c1.task":
    "Il pezzo 1 è x = 1 − t², y = t su [0, 1]. Scrivi x(t) e y(t) del pezzo 2 su [1, 2] in modo che la giunzione in t = 1 sia C¹: lo stesso punto e la stessa velocità da entrambi i lati.",
  "exercise.piecewise-c1.hint":
    "In t = 1 il pezzo 1 si trova in x = 0, y = 1 con velocità x′ = −2, y′ = 1. Tieni y = t e cerca x = t² + bt + c con x(1) = 0 e x′(1) = 2 + b = −2.",
  "exercise.piecewise-c1.notYet":
    "Non ancora. Il verdetto del nucleo di calcolo in t = 1: {detail}.",
  // ---- parametric-curve (section 1) ----
  "parametricCurve.title": "Curve parametriche da formule",
  "parametricCurve.summary":
    "Scrivi x(t), y(t) (e z(t)) e guarda un punto percorrere P(t) con la sua velocità, l'accelerazione, la curvatura e il cerchio osculatore, con l'odografo accanto.",
  "parametricCurve.aria":
    "Curva parametrica x(t) = {x}, y(t) = {y} per t da {a} a {b}; t = {t}; P(t) = ({px}; {py}); modulo della velocità {speed}; curvatura κ = {kappa}; l'odografo è disegnato accanto",
  "parametricCurve.aria3d":
    "Curva nello spazio x(t) = {x}, y(t) = {y}, z(t) = {z} per t da {a} a {b}; t = {t}; P(t) = ({px}; {py}; {pz}); modulo della velocità {speed}; curvatura κ = {kappa}; torsione τ = {tau}; il triedro di Frenet T, N, B è disegnato in P(t)",
  "parametricCurve.ariaUndefined":
    "Curva parametrica x(t) = {x}, y(t) = {y} per t da {a} a {b}; in t = {t} la curva non è definita",
  "parametricCurve.whatYouSee":
    "Una curva è un punto che si muove: P(t) = (x(t), y(t)) per t in [a, b] (sezione 1 del programma; la circonferenza x = cos t, y = sin t su [0, 2π] delle dispense). La freccia vermiglia è la velocità P′(t), quella viola l'accelerazione P″(t); la circonferenza arancione è il cerchio osculatore di raggio 1/|κ|. A destra l'odografo raccoglie tutte le velocità P′(t), disegnate dal punto O. Ogni formula è analizzata e derivata dalla libreria delle curve; ogni nome diverso da t diventa un cursore.",
  "parametricCurve.try1":
    "Premi “Avvia”, poi scegli “Cicloide”: in ogni cuspide il modulo della velocità scende a 0 e la freccia della velocità sparisce, mentre l'odografo passa per O.",
  "parametricCurve.try2":
    "Scegli “Ellisse” e muovi i cursori a e b: il cerchio osculatore è più piccolo agli estremi dell'asse maggiore.",
  "parametricCurve.try3":
    "Scegli “y = tan t”: il grafico si interrompe nei poli t = ±π/2 invece di unire i rami.",
  "parametricCurve.try4":
    "Scegli “Il polinomio delle dispense” e spunta “Mostra la forma di Bézier”: i punti di controllo sono frazioni esatte come −271/50.",
  "parametricCurve.try5":
    "Scrivi sin(t) in z(t): la curva esce dal piano e in P(t) compare il triedro di Frenet T, N, B. Trascina la figura per ruotarla.",
  "parametricCurve.control.curve": "Curva P(t)",
  "parametricCurve.control.x": "x(t) =",
  "parametricCurve.control.y": "y(t) =",
  "parametricCurve.control.z": "z(t) = (vuoto: una curva piana)",
  "parametricCurve.control.from": "t da",
  "parametricCurve.control.to": "a",
  "parametricCurve.control.help":
    "Formule in t come 2cos(t), t^2 - 1, e^(-t/5)sin(3t); π si scrive pi. Ogni altra lettera (a, b, ω, a_1) è un parametro con il suo cursore.",
  "parametricCurve.control.params": "Parametri",
  "parametricCurve.control.param.input": "valore del parametro {name}",
  "parametricCurve.control.t": "t",
  "parametricCurve.control.t.input": "valore del parametro t",
  "parametricCurve.control.examples": "Esempi",
  "parametricCurve.preset.circle": "Circonferenza",
  "parametricCurve.preset.ellipse": "Ellisse",
  "parametricCurve.preset.lissajous": "Lissajous",
  "parametricCurve.preset.cycloid": "Cicloide",
  "parametricCurve.preset.cardioid": "Cardioide",
  "parametricCurve.preset.astroid": "Astroide",
  "parametricCurve.preset.spiral": "Spirale",
  "parametricCurve.preset.helix": "Elica (3D)",
  "parametricCurve.preset.tan": "y = tan t",
  "parametricCurve.preset.polynomial": "Il polinomio delle dispense",
  "parametricCurve.control.bezier": "Mostra la forma di Bézier (una curva polinomiale)",
  "parametricCurve.bezierPoints": "Punti di controllo su [{a}, {b}], esatti: {list}",
  "parametricCurve.bezierLink": "Apri questi punti di controllo nell'algoritmo di De Casteljau",
  "parametricCurve.bezierLinkOff":
    "La dimostrazione di De Casteljau accetta solo curve piane di grado da 1 a 10.",
  "parametricCurve.atT": "In t",
  "parametricCurve.speed": "Modulo della velocità |P′(t)| = {speed}",
  "parametricCurve.curvature": "Curvatura κ(t) = {kappa}",
  "parametricCurve.radius": "Cerchio osculatore di raggio {r}",
  "parametricCurve.torsion": "Torsione τ(t) = {tau}",
  "parametricCurve.undefined": "La curva non è definita in t = {t} (un polo o un buco)",
  "parametricCurve.cusp": "P′(t) = 0: nessuna direzione di moto, κ non è definita",
  "parametricCurve.straight": "Dritta qui (κ ≈ 0): nessun cerchio osculatore",
  "parametricCurve.pointLabel": "P(t)",
  "parametricCurve.velocityLabel": "P′(t)",
  "parametricCurve.accelerationLabel": "P″(t)",
  "parametricCurve.originLabel": "O",
  "parametricCurve.tangentLabel": "T",
  "parametricCurve.normalLabel": "N",
  "parametricCurve.binormalLabel": "B",
  "parametricCurve.hodographCaption": "Odografo P′(t), origine O",
  "parametricCurve.scaleCaption": "Frecce e odografo in scala {scale}",
  "parametricCurve.frameCaption":
    "Triedro di Frenet T, N, B in P(t); trascina per ruotare, Maiusc+trascina per spostare",
  "parametricCurve.incomplete":
    "Disegnata in modo approssimato: da qualche parte la curva oscilla più in fretta di quanto il disegno abbia potuto seguire",
  "parametricCurve.formula.undefined": "non definito",
  "parametricCurve.formula.tooLong": "troppo lunga da mostrare",
  "parametricCurve.error.text": "campo “{field}”: una formula è un testo di al più {max} caratteri",
  "parametricCurve.error.params":
    'campo “params”: i valori dei parametri sono numeri finiti per nome, come {"a": 2}',
  // ---- end parametric-curve ----
  // ---- sketch (section 7, www/demos/sketch.js) and its exercise ----
  "sketch.title": "Abbozzare una curva",
  "sketch.summary":
    "Disegna un tratto: il minimo di pezzi di Bézier (o di punti di controllo di una B-spline) che restano entro la tolleranza, con gli spigoli conservati; poi modifica trascinando i punti o ridisegnando una parte.",
  "sketch.aria": "Curva abbozzata: {fit}",
  "sketch.figureHelp":
    "Disegna sulla figura con il mouse, una penna o un dito; un tratto che parte sulla curva ridisegna quella parte. Trascina un punto, oppure premi Tab per selezionarne uno e le frecce per spostarlo (Maiusc: 10 px). Maiusc + trascinamento sposta la vista; rotella o pizzico per lo zoom.",
  "sketch.outputLegend": "La curva è",
  "sketch.output.G1": "pezzi di Bézier, giunzioni G¹",
  "sketch.output.C1": "pezzi di Bézier, giunzioni C¹",
  "sketch.output.bspline": "una B-spline di grado p",
  "sketch.control.degree": "Grado p",
  "sketch.control.degree.input": "grado della B-spline",
  "sketch.control.tolerance": "Tolleranza (px dello schermo)",
  "sketch.control.tolerance.input": "tolleranza in pixel dello schermo",
  "sketch.showLegend": "Mostra",
  "sketch.control.corners": "spigoli (e la svolta in ciascuno)",
  "sketch.control.breaks": "punti di divisione (giunzioni)",
  "sketch.control.errors": "l'errore massimo di ogni pezzo e il suo campione",
  "sketch.control.polygon": "poligoni e punti di controllo (trascinali)",
  "sketch.control.comb": "pettine di curvatura",
  "sketch.control.oversketch": "Un tratto che parte sulla curva ridisegna quella parte",
  "sketch.oversketchBezier":
    "Ridisegnare una parte modifica pezzi di Bézier: con una B-spline ogni tratto è un nuovo disegno.",
  "sketch.control.presets": "Tratti di esempio",
  "sketch.preset.wave": "Onda",
  "sketch.preset.corners": "Zigzag con spigoli",
  "sketch.preset.blob": "Forma chiusa",
  "sketch.preset.spiral": "Spirale",
  "sketch.preset.letter": "Lettera S",
  "sketch.pieces.one": "{count} pezzo",
  "sketch.pieces.many": "{count} pezzi",
  "sketch.pieces.other": "{count} pezzi",
  "sketch.corners.one": "{count} spigolo",
  "sketch.corners.many": "{count} spigoli",
  "sketch.corners.other": "{count} spigoli",
  "sketch.controlPoints.one": "{count} punto di controllo",
  "sketch.controlPoints.many": "{count} punti di controllo",
  "sketch.controlPoints.other": "{count} punti di controllo",
  "sketch.fitPieces":
    "{pieces}, {corners}; errore massimo {error} (tolleranza {tolerance} px); {shape}.",
  "sketch.fitBSpline":
    "B-spline di grado {p} con {control}; errore massimo {error} (tolleranza {tolerance} px); {shape}.",
  "sketch.px": "{value} px",
  "sketch.notMeasured": "non misurato",
  "sketch.open": "aperta",
  "sketch.closed": "chiusa",
  "sketch.edited":
    "Modificata dopo l'approssimazione: i segni e gli errori sono quelli dell'approssimazione, prima delle modifiche.",
  "sketch.handle": "pezzo {piece}, {name}",
  "sketch.badStroke": "il tratto non è un codice di tratto valido (da 2 a 4000 punti)",
  "sketch.badEdits": "l'elenco delle modifiche non è valido",
  "sketch.whatYouSee":
    "La linea larga e chiara è ciò che hai disegnato; la curva blu è l'approssimazione della libreria: pezzi di Bézier cubici, il meno possibile perché ogni campione del tratto resti entro la tolleranza ε (misurata, non stimata), oppure una B-spline di grado p con il minimo di punti di controllo. Dove il tratto svolta bruscamente l'approssimazione conserva uno spigolo (una giunzione G⁰, il segno quadrato con l'angolo di svolta); ogni altra giunzione è liscia, G¹ o C¹. I punti verdi sono i punti di divisione, le linee tratteggiate il poligono di controllo di ogni pezzo, e il pettine mostra la curvatura κ lungo la curva. Sezione 7 del programma (progettazione interattiva): “una curva più o meno così”, modificata senza ricominciare da capo.",
  "sketch.try1":
    "Disegna in fretta uno zigzag, poi porta la tolleranza da 1 px a 10 px: i pezzi si fondono, ma gli spigoli restano.",
  "sketch.try2":
    "Disegna un anello che finisce dove è iniziato: la curva si chiude, liscia sulla cucitura. Attiva il pettine di curvatura: dove salta κ?",
  "sketch.try3":
    "Inizia un tratto breve sulla curva e finiscilo sulla curva più avanti: viene ridisegnata solo quella parte. Poi trascina un punto di controllo e premi Ctrl+Z.",
  "exercise.sketch-pieces.title": "Una forma in pochi pezzi",
  "exercise.sketch-pieces.task":
    "Disegna una forma chiusa con almeno uno spigolo (una goccia, una foglia, una casetta) che l'approssimazione con tolleranza 3 px costruisce con al massimo 6 pezzi di Bézier.",
  "exercise.sketch-pieces.hint":
    "Torna al punto di partenza perché la curva si chiuda; disegna con calma (un tratto tremolante richiede più pezzi), dagli una svolta netta e tieni la tolleranza a 3 px o più.",
  "exercise.sketch-pieces.notYet": "Non ancora: {detail}.",
  "exercise.sketch-pieces.detail": "{pieces}, {corners}, {shape}",
  // ---- end sketch ----
};
